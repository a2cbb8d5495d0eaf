// One federation execution as the gateway sees it: the coordinator of the joined federates and of one
// state type per service group (server/<group>.hpp), whose handlers (server/<group>.cpp) route each request
// between them. Pure state, no I/O: messages for federates are encoded into buffers handed out by an Outbox.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "fed_parser/fom.hpp"
#include "fed_parser/omt.hpp"
#include "rti/exceptions.hpp"
#include "rti/server/declarations.hpp"
#include "rti/server/name_reservations.hpp"
#include "rti/server/objects.hpp"
#include "rti/server/outbox.hpp"
#include "rti/server/regions.hpp"
#include "rti/server/save_restore.hpp"
#include "rti/server/sync_points.hpp"
#include "rti/server/time_manager.hpp"
#include "rti/server/update_rates.hpp"
#include "rti/wire/codec.hpp"

namespace hlacore {

class Federation {
public:
    Federation(std::string name, fom::Fom fom, std::string fed_name, std::string fed_text, Outbox& outbox);

    const std::string& name() const { return name_; }
    const fom::Fom& fom() const { return fom_; }
    const std::string& fed_name() const { return fed_name_; }
    const std::string& fed_text() const { return fed_text_; }
    bool has_federates() const { return !federates_.empty(); }
    std::size_t federate_count() const { return federates_.size(); }

    // Federation management. join throws FederateAlreadyExecutionMember for a name in use; resign throws
    // FederateOwnsAttributes when the action would leave attributes owned by a departed federate.
    FederateHandle join(const std::string& federate_name, const std::string& federate_type = "");
    // Sends a new federate what it must hear first (announcements of pending synchronization points).
    void announce_pending(FederateHandle federate);
    // A federate joined with FOM modules of its own (IEEE 1516-2010 §4.5): the FOM becomes `extended` (every
    // handle kept), each other federate is sent it (FomExtended) and regions span the dimensions it adds.
    void extend_fom(fom::ExtendedFom extended, FederateHandle joining);
    void resign(FederateHandle federate, wire::ResignAction action);

    // Returns (object handle, object name). Throws ObjectAlreadyRegistered for a name in use.
    std::pair<ObjectHandle, std::string> register_object(FederateHandle federate, fom::Handle object_class,
                                                         const std::string& name);

    // registerObjectInstanceWithRegion (HLA 1.3 §9.5): register_object with the attributes' update regions
    // in place before anyone discovers the instance (server/regions.cpp).
    std::pair<ObjectHandle, std::string> register_object_with_region(FederateHandle federate,
                                                                     const wire::RegisterObjectWithRegion& m);

    // attributeOwnershipReleaseResponse (HLA 1.3 §7.11): returns the attributes actually released, those
    // some federate is waiting to acquire.
    wire::Handles release_response(FederateHandle federate, const wire::ReleaseResponse& m);

    // What the recording (server/recorder.cpp) names things by: "" and null for handles that name nothing.
    const std::string& federate_name(FederateHandle federate) const;
    std::vector<FederateHandle> federates() const;  // the joined ones, in the order they joined
    const ObjectInstance* object(ObjectHandle object) const;
    double federate_time(FederateHandle federate) const;
    bool regulating(FederateHandle federate) const { return federates_.count(federate) && time_.regulating(federate); }

    // LBTS or the minimum next event time of a federate (HLA 1.3 §8.16, §8.18).
    double query_time(FederateHandle federate, wire::TimeQuery which);
    // Appends this federation's state as a JSON object (federates, time state, objects, sync points), with
    // every object instance and its owners if `instances`; `more` appends a federate's fields the federation
    // does not know (the gateway's: its connection's backlog).
    void write_status(std::string& json, bool instances,
                      const std::function<void(FederateHandle, std::string&)>& more = {});
    // What waits in the federation for `federate` until its own time state moves (flow control counts it).
    std::size_t held_bytes(FederateHandle federate) const { return time_.held_bytes(federate); }
    // Where the messages time management holds for a federate go beyond `above` bytes (the gateway's spill).
    void attach_parking(FrameParking* parking, std::size_t above) { time_.attach_parking(parking, above); }

    // ---- save/restore (HLA 1.3 §4.11-4.22; cpp/rti/server/save_restore.cpp, docs/save-restore.md) ----
    // Where saves are written as files ("" keeps them in memory only).
    void set_save_dir(std::string dir) { save_restore_.dir = std::move(dir); }
    // The reading of the time rules it follows (rti/time.hpp), chosen at its creation.
    void set_time_semantics(TimeSemantics semantics) { time_.set_semantics(semantics); }
    TimeSemantics time_semantics() const { return time_.semantics(); }
    void set_time_type(TimeType type) { time_type_ = type; }
    TimeType time_type() const { return time_type_; }
    // requestFederationSave: throws SaveInProgress, RestoreInProgress, FederationTimeAlreadyPassed,
    // InvalidFederationTime.
    void request_save(FederateHandle federate, const std::string& label, const wire::OptionalTime& time);
    // requestFederationRestore: throws SaveInProgress, RestoreInProgress; a save that is missing, corrupt
    // or does not fit the joined federates is answered with requestFederationRestoreFailed.
    void request_restore(FederateHandle federate, const std::string& label);
    // IEEE 1516-2010's abortFederationSave and abortFederationRestore: every federate is told the save or
    // restore failed, aborted. Throw SaveNotInProgress, RestoreNotInProgress.
    void abort_save(FederateHandle federate);
    void abort_restore(FederateHandle federate);
    // Joining and resigning are refused during a save or a restore (SaveInProgress, RestoreInProgress).
    void check_membership_change(const char* service) const;

    // Everything else a federate sends once joined, by type (the gateway's dispatcher has visited the
    // message already). Handles are checked against the FOM (a bad one is a protocol violation:
    // wire::WireError); objects that vanished meanwhile are ignored.
    template <class M>
    void handle(FederateHandle from, const M& message);

private:
    struct FederateState;

    // ---- data distribution management (HLA 1.3 §9): the state in server/regions.hpp, the routing in
    // server/regions.cpp ----
    // WireError unless the class's attribute is in the routing space of the federate's region `r`.
    void check_region_space(const fom::ObjectClass& cls, fom::Handle attribute, RegionHandle r,
                            const Region& region) const;
    // The federate's region `r`, which must be in the routing space of interaction class `cls` (WireError).
    const Region& interaction_region(const FederateState& f, RegionHandle r, fom::Handle cls) const;
    // The regions `owner` updates the attribute of the object in (none: the default region).
    SentRegions update_regions_of(FederateHandle owner, ObjectHandle object, fom::Handle attribute) const;
    // Is the attribute subscribed at class `known` through a region overlapping some update region of the owner's?
    bool region_wanted(const FederateState& g, fom::Handle known, FederateHandle owner, ObjectHandle object,
                       fom::Handle attribute) const;
    // Does federate `gh` discover the object now: a plain subscription to its class (as before DDM), or
    // an owned attribute in scope through one of its subscription regions.
    bool discovers(FederateHandle gh, const FederateState& g, ObjectHandle object, const ObjectInstance& obj) const;
    // The class a federate receives an interaction sent in `sent_in` as, or 0.
    fom::Handle interaction_receiver(const FederateState& g, fom::Handle cls, const SentRegions& sent_in) const;
    void discover_in_scope();  // after regions, associations or subscriptions changed
    // After the FOM gained dimensions: each region spans the new ones whole, as one that does not name them.
    void widen_regions();
    // The known object's attributes in scope for federate `gh` (HLA 1.3 §6.13).
    std::set<fom::Handle> scope_of(FederateHandle gh, const FederateState& g, ObjectHandle object,
                                   const ObjectInstance& obj) const;
    // Sends attributesInScope / attributesOutOfScope (scope switch) and turnUpdatesOn/OffForObjectInstance
    // (attribute relevance switch: some other federate has the owned attribute in scope) to the federates
    // whose switch is on; after each request.
    void refresh_scope();
    // After a scope or relevance switch changed or a federate left: how many federates watch scope.
    void count_scope_watchers();
    void forget_update_regions(ObjectHandle object);
    void route_interaction(FederateHandle from, const wire::SendInteractionView& m, const SentRegions& sent_in);
    // requestClassAttributeValueUpdate, plain (region null) or with a region (objects.cpp).
    void request_class_update(FederateHandle from, fom::Handle cls, const wire::Handles& attributes,
                              const Region* region);
    // ---- end of data distribution management ----

    struct FederateState {
        std::string name;
        std::string type;  // as it joined (IEEE 1516-2010; "" in HLA 1.3)
        FederateDeclarations declarations;  // declaration management (HLA 1.3 §5, server/declarations.hpp)
        std::set<ObjectHandle> known;       // registered or discovered, not locally deleted
        // changeInteractionOrderType / changeInteractionTransportationType (HLA 1.3 §6.20, §6.22): this
        // federate's interactions of a class go this way instead of the FOM's, until it unpublishes the class.
        std::map<fom::Handle, fom::Order> interaction_order;
        std::map<fom::Handle, fom::Transport> interaction_transport;
        FederateRegions ddm;  // data distribution management (HLA 1.3 §9, server/regions.hpp)
        std::optional<UpdateRateLimits> rates;  // once it subscribes with an update rate (IEEE 1516-2010)
        // For the status report, whose readers (hlacore.monitor) turn them into rates and waits.
        std::uint64_t updates_sent = 0, interactions_sent = 0, grants = 0;
        std::chrono::steady_clock::time_point requested_at{};  // its last time advance request
    };
    // Ownership callbacks gathered while handling one request, one message per federate and kind; the
    // requests for assumption and release carry the request's tag.
    struct OwnershipNotices {
        std::map<FederateHandle, wire::Handles> acquired, divested, unavailable, cancelled;
        std::map<FederateHandle, wire::Handles> assumption_requested, release_requested;
        std::string tag;
    };

    FederateState& federate(FederateHandle h);
    const fom::ObjectClass& object_class(fom::Handle h) const;
    const fom::InteractionClass& interaction_class(fom::Handle h) const;
    void check_attributes(const fom::ObjectClass& cls, const wire::Handles& attributes) const;

    // The class a federate knows instances of `cls` as: the nearest (self included) subscribed class, or 0.
    fom::Handle known_class(const FederateState& f, fom::Handle cls) const;
    fom::Handle receiving_interaction_class(const FederateState& f, fom::Handle cls) const;
    void discover(FederateHandle to, FederateState& f, ObjectHandle object, const ObjectInstance& instance);
    void discover_all_for(FederateHandle to);
    void remove_object(ObjectHandle object, FederateHandle by, const std::string& tag, const wire::OptionalTime& time,
                       std::uint64_t serial);
    void update_advisories();
    // One kind of advisory for the publisher `ph`: On for each published class that some other federate
    // `receives` and that `announced` lacks, Off for each announced one still published but no longer
    // received; `announced` becomes the received ones.
    template <class On, class Off, class Published, class Receives>
    void advise(FederateHandle ph, const Published& published, std::set<fom::Handle>& announced, Receives receives);
    // Does the federate publish `attribute` for the object's class (or a superclass of it)?
    bool publishes(const FederateState& f, const ObjectInstance& obj, fom::Handle attribute) const;
    // attributeOwnershipAcquisition(IfAvailable): transfers what is free to take; returns the rest that
    // another federate owns, with its owner.
    std::vector<std::pair<fom::Handle, FederateHandle>> acquire_available(FederateHandle from, const FederateState& f,
                                                                          ObjectInstance& obj,
                                                                          const wire::Handles& attributes,
                                                                          OwnershipNotices& notices);
    // Ownership moves (HLA 1.3 §7): `to` becomes the owner; a negotiating previous owner is told.
    void transfer(ObjectInstance& obj, fom::Handle attribute, FederateHandle to, OwnershipNotices& notices);
    // The attribute loses its owner; the first federate waiting to acquire it gets it.
    void release_attribute(ObjectInstance& obj, fom::Handle attribute, OwnershipNotices& notices);
    void send_notices(ObjectHandle object, OwnershipNotices& notices);
    // An ownership request naming attributes of an object: nothing when the object vanished meanwhile,
    // else `act(object, notices)`, after which the notices it gathered are sent. False when it vanished.
    template <class Act>
    bool change_ownership(FederateHandle from, ObjectHandle object, const wire::Handles& attributes, Act&& act);
    // Drops the owner's transport and order changes of an attribute that changes owner.
    static void forget_delivery(ObjectInstance& obj, fom::Handle attribute);
    // The object a federate names in an ownership service, or null when it vanished meanwhile; its
    // attribute handles are checked against the FOM.
    ObjectInstance* owned_object(ObjectHandle object, const wire::Handles& attributes);
    // Sends what time management allows now: held messages, TSO messages, grants and enable callbacks.
    void release_time();
    // Throws WireError for a timestamp below a regulating sender's bound; `what` names the message.
    void check_timestamp(FederateHandle from, double time, const char* what) const;
    // Receive-order delivery, held back from a constrained federate that is not advancing.
    template <class M>
    void deliver_receive_order(FederateHandle to, const M& message);
    // Timestamp-ordered delivery: `frame` (the message encoded) queued until the receiver's grant allows it.
    // `routed`: the message's routing record (for a retraction), found at its first receiver and kept by the
    // caller for the others.
    struct Routed;
    template <class M>
    void deliver_timestamp_order(FederateHandle to, const M& message, FederateHandle sender, std::uint64_t serial,
                                 double time, Routed*& routed, wire::SharedFrame frame);
    // WireError for a parameter the class does not define (the sender's client checked it).
    void check_parameters(const fom::InteractionClass& cls, const wire::HandleValueViews& values) const;
    // How the sender's interactions of the class go: its change of their transport or order (HLA 1.3 §6.20,
    // §6.22), else the FOM's.
    std::pair<fom::Transport, fom::Order> interaction_delivery(const FederateState& sender,
                                                               const fom::InteractionClass& cls) const;
    // An interaction (ForwardedInteraction, ForwardedDirectedInteraction: sender, serial, tag and transport set)
    // to federate `to`, received as class `as` with the values that class defines: in timestamp order at
    // `time`, in receive order without one.
    template <class Forwarded>
    void forward_interaction(FederateHandle to, Forwarded& receive, const wire::HandleValueViews& values, fom::Handle as,
                             const wire::OptionalTime& time, Routed*& routed);
    // The class federate `gh` receives an interaction of `cls` directed at `obj` as (HLA 4), or 0.
    fom::Handle directed_receiver(FederateHandle gh, const FederateState& g, fom::Handle cls,
                                  const ObjectInstance& obj) const;

    // The handlers, one per message of HLACORE_FEDERATION_SERVICES (wire/message_list.hpp), each defined in
    // the server file of its group; anything else is a protocol violation.
#define HLACORE_X(name) void on(FederateHandle from, const wire::name& m);
    HLACORE_FEDERATION_SERVICES(HLACORE_X)
#undef HLACORE_X
    // Updates and interactions as the gateway serves them, their values views into the frame (the handlers
    // above of the owned messages, from datagrams, view them and come here).
    void on(FederateHandle from, const wire::UpdateAttributesView& m);
    void on(FederateHandle from, const wire::SendInteractionView& m);
    template <class M>
    void on(FederateHandle from, const M& m);

    // ---- save/restore (cpp/rti/server/save_restore.cpp) ----
    struct Snapshot;  // a decoded save
    // Once every joined federate answered: whether they all succeeded and none left. Empty until then.
    std::optional<bool> outcome(const SaveRestore::Run& run) const;
    // Ends `run`: each federate is sent `done` (federationSaved, federationRestored), then what was held for it.
    template <class R, class M>
    void end_run(R& run, const M& done);
    // Tells the federates that may save now (all of them, or for a timed save those granted its time).
    void tell_savers();
    // During a timed save, time-managed federates not yet told are granted at most the save time.
    void cap_requests_at_save_time();
    void finish_save_if_answered();
    void finish_restore_if_answered();
    void finish_save(const wire::FederationSaved& done);
    void finish_restore(const wire::FederationRestored& done);
    std::string encode_snapshot() const;
    Snapshot decode_snapshot(const std::string& bytes) const;  // throws wire::WireError
    // Hooks into the rest of the federation: grants and deliveries wait while every federate saves or
    // restores; what is sent to a federate saving or restoring is held (Outbox::holding).
    bool time_frozen() const;
    // Delivers frames held during a save or restore: receive-order ones as deliver_receive_order would.
    void deliver_held(FederateHandle to, std::vector<std::string>& frames);
    void save_restore_departed(FederateHandle federate);
    void write_save_status(std::string& json) const;
    void write_instances(std::string& json) const;

    std::string name_;
    fom::Fom fom_;
    std::string fed_name_;
    std::string fed_text_;
    TimeType time_type_ = TimeType::Float64;
    Outbox& outbox_;
    FederateHandle next_federate_ = 1;
    ObjectHandle next_object_ = 1;
    std::map<FederateHandle, FederateState> federates_;
    std::map<ObjectHandle, ObjectInstance> objects_;
    std::unordered_map<std::string, ObjectHandle> object_names_;
    SyncPoints sync_points_{outbox_};
    NameReservations reservations_{outbox_};
    std::size_t scope_watchers_ = 0;  // federates with the attribute scope or relevance switch on

    TimeManager time_;
    // TSO messages routed but perhaps not yet delivered, for retraction: sender -> serial -> receivers.
    struct Routed {
        double time = 0;
        std::vector<FederateHandle> receivers;
    };
    std::map<FederateHandle, std::map<std::uint64_t, Routed>> routed_;

    SaveRestore save_restore_;
};

}  // namespace hlacore
