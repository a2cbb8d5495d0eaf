// The federate side of the connection to a gateway: HLA 1.3 services with local validation against
// the FOM and the federate's own declarations, and a queue of callbacks waiting to be evoked by tick.
//
// Thread safety: every public method may be called from any thread. Reading the socket is done by
// whichever thread waits (tick or a service awaiting its reply); the others wait on a condition variable.
//
// Liveness (docs/robustness.md): a thread that waits pings a gateway silent for half the timeout and
// declares it not responding (GatewayNotResponding, the connection closed) when it stays silent for the
// whole timeout; a send the gateway does not read for the timeout fails the same way. A signal during a
// wait goes to the WaitHost, which may abandon the call; a call abandoned while its reply or its frame is
// owed closes the connection (the gateway then resigns the federate), so no state is left half known.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

#include <poll.h>
#include <sys/uio.h>

#include "fed_parser/fom.hpp"
#include "rti/exceptions.hpp"
#include "rti/client/options.hpp"
#include "rti/net/wait.hpp"
#include "rti/record/mcap.hpp"
#include "rti/time.hpp"
#include "rti/tls.hpp"
#include "rti/update_regions.hpp"
#include "rti/wire/codec.hpp"
#include "rti/wire/datagram.hpp"
#include "rti/wire/read_buffer.hpp"

namespace hlacore {

// The client's datagram path: whether best-effort messages travel as datagrams, and the counts both ways.
struct DatagramStatus {
    bool path = false;
    std::string reason;  // why not, when not
    wire::DatagramStats counts;
};

// The offset of the gateway's steady clock from this process's (gateway = local + offset_s), known to within
// ± uncertainty_s (half the round trip of the best probe: NTP's bound, which holds whatever the asymmetry
// of the path), measured at `measured_at`.
struct ClockEstimate {
    double offset_s = 0;
    double uncertainty_s = 0;
    std::chrono::steady_clock::time_point measured_at{};
};

class Client {
public:
    using Clock = std::chrono::steady_clock;
    enum class WaitStatus { Ready, Timeout, Interrupted };

    // Connects and performs the version handshake (and the authentication, when the gateway asks for it);
    // throws RtiError naming the address: RTIinternalError when nothing listens there, GatewayNotResponding
    // when it does not answer within the timeout, AuthenticationFailed without the right secret.
    Client(const std::string& host, std::uint16_t port, ClientOptions options = {});
    ~Client();
    Client(const Client&) = delete;
    Client& operator=(const Client&) = delete;

    const std::string& address() const { return address_; }
    // The clock offset to the gateway, measured on the first call and again when older than max_age_s
    // (four round trips; docs/networking.md).
    ClockEstimate clock_offset(double max_age_s);
    int fileno() const { return fd_; }
    int datagram_fileno() const { return datagram_path_ ? datagram_fd_ : -1; }  // beside fileno() for select()
    DatagramStatus datagram_status() const;

    // A request of HLACORE_CLIENT_REQUESTS (wire/message_list.hpp): its check in client/<group>.cpp, then the send.
    template <class M>
    void request(const M& message) {
        {
            std::lock_guard<std::mutex> lock(mu_);
            check(message);
        }
        send(message);
    }

    // ---- federation management ----
    void create_federation(const std::string& name, const std::string& fed_name, const std::string& fed_text,
                           TimeType time_type = TimeType::Float64);
    void destroy_federation(const std::string& name);
    // `fom_modules`: FOM modules this federate adds to the federation's (IEEE 1516-2010 §4.5), a bundle
    // (fom::bundle), read and checked by the caller; the gateway refuses what does not fit with ErrorReadingFED
    // or InconsistentFDD, and on success every federate joined before learns the extended FOM (FomExtended).
    std::uint32_t join(const std::string& federate, const std::string& federation, const std::string& fom_modules = "",
                       const std::string& federate_type = "");
    void resign(std::uint8_t action);

    // ---- declaration management ----
    void publish_object_class(fom::Handle cls, const std::vector<fom::Handle>& attributes);
    void unpublish_object_class(fom::Handle cls);

    // ---- object management; the update calls return the serial of the event retraction handle ----
    std::uint32_t register_object(fom::Handle cls, const std::string& name);
    // The values are views: what they view must outlive the call (it is encoded before the call returns).
    std::uint64_t update_attributes(std::uint32_t object, wire::HandleValueViews values, const std::string& tag,
                                    wire::OptionalTime time);
    std::uint64_t send_interaction(fom::Handle cls, wire::HandleValueViews values, const std::string& tag,
                                   wire::OptionalTime time);
    std::uint64_t delete_object(std::uint32_t object, const std::string& tag, wire::OptionalTime time);

    // ---- HLA 4's directed interactions (client/directed.cpp; the routing in server/directed.cpp) ----
    // Adds the interaction classes to those published directed at instances of the object class, or removes
    // them (all when none are named).
    void publish_directed(fom::Handle object_class, const std::vector<fom::Handle>& interactions, bool adding);
    // Received when this federate owns an attribute of the instance, whenever it knows the instance, or no more
    // (None: all of the class's when none are named).
    enum class DirectedReceipt : std::uint8_t { None, Owned, Universally };
    void subscribe_directed(fom::Handle object_class, const std::vector<fom::Handle>& interactions,
                            DirectedReceipt receipt);
    // The checks of a declaration that changes nothing (no interaction class to withdraw): ObjectClassNotDefined,
    // a save or restore under way.
    void check_directed_declaration(fom::Handle object_class) const;
    // InteractionClassNotPublished unless published directed at the class the object is known as (or a superclass).
    std::uint64_t send_directed_interaction(fom::Handle cls, std::uint32_t object, wire::HandleValues values,
                                            const std::string& tag, wire::OptionalTime time);

    // ---- transport and order changes (HLA 1.3 §6.19-6.22) ----
    // Handles are fom::Transport / fom::Order values (InvalidTransportationHandle / InvalidOrderingHandle
    // otherwise). They apply to this federate's later updates of the owned attributes (forgotten by the
    // gateway when the attribute changes owner or the object is deleted) and its later interactions of a
    // published class (until it unpublishes it).
    void change_attribute_transportation(std::uint32_t object, const std::vector<fom::Handle>& attributes,
                                         std::uint32_t transport);
    void change_attribute_order(std::uint32_t object, const std::vector<fom::Handle>& attributes,
                                std::uint32_t order);
    void change_interaction_transportation(fom::Handle cls, std::uint32_t transport);
    void change_interaction_order(fom::Handle cls, std::uint32_t order);

    // ---- ownership management (HLA 1.3 §7) ----
    // The federate's owned attributes change when the notifications are popped (acquisition, divestiture)
    // or when a call gives them up (unconditional divestiture, release response).
    void unconditional_divestiture(std::uint32_t object, const std::vector<fom::Handle>& attributes);
    void negotiated_divestiture(std::uint32_t object, const std::vector<fom::Handle>& attributes,
                                const std::string& tag);
    void ownership_acquisition(std::uint32_t object, const std::vector<fom::Handle>& attributes,
                               const std::string& tag);
    void ownership_acquisition_if_available(std::uint32_t object, const std::vector<fom::Handle>& attributes);
    // Returns the attributes actually released (those another federate is waiting for).
    std::vector<fom::Handle> release_response(std::uint32_t object, const std::vector<fom::Handle>& attributes);
    bool is_owned(std::uint32_t object, fom::Handle attribute) const;

    // ---- data distribution management (HLA 1.3 §9), client/regions.cpp ----
    // A region's handle is chosen here (regions belong to their creator). An extent lists closed ranges
    // (dimension, lower, upper) with kMinExtent <= lower <= upper <= kMaxExtent; the dimensions it does not
    // list span the whole axis.
    static constexpr std::int64_t kMinExtent = 0;
    static constexpr std::int64_t kMaxExtent = 0xFFFFFFFF;
    struct Range {
        fom::Handle dimension = 0;
        std::int64_t lower = 0;
        std::int64_t upper = 0;
    };
    using Extent = std::vector<Range>;
    std::uint32_t create_region(fom::Handle space, const Extent& extent);
    // notifyAboutRegionModification: the region takes `extent` (or keeps its own) from the next message on.
    void modify_region(std::uint32_t region, const std::optional<Extent>& extent);
    void delete_region(std::uint32_t region);
    // The region's routing space and its ranges, one per dimension of the space in the FOM's order.
    std::pair<fom::Handle, Extent> region_extent(std::uint32_t region) const;
    // The regions this federate holds, in handle order (after a restore: the saved ones).
    std::vector<std::uint32_t> regions() const;
    // Each (attribute, region) pair associates; an attribute named twice keeps its last region when `adds` is
    // false (HLA 1.3: one region an attribute), all of them when true (IEEE 1516-2010).
    std::uint32_t register_object_with_region(fom::Handle cls,
                                              const std::vector<std::pair<fom::Handle, std::uint32_t>>& regions,
                                              const std::string& name, bool adds = false);
    // Sent in these regions (HLA 1.3: one; IEEE 1516-2010: any number, none being the default region).
    std::uint64_t send_interaction_with_region(fom::Handle cls, wire::HandleValues values, wire::Handles regions,
                                               const std::string& tag, wire::OptionalTime time);

    // ---- time management (HLA 1.3 §8; the rules are in docs/time-management.md) ----
    // The federate's time state changes when its callbacks are popped (timeRegulationEnabled,
    // timeConstrainedEnabled, timeAdvanceGrant), as HLA says: at delivery, not at arrival.
    void enable_time_regulation(Time time, Time lookahead);
    void disable_time_regulation();
    void enable_time_constrained();
    void disable_time_constrained();
    void time_advance(AdvanceKind kind, Time time);
    void modify_lookahead(Time lookahead);
    Time query_lookahead() const;
    Time query_federate_time() const;
    Time query_lbts();
    Time query_min_next_event_time();
    void set_asynchronous_delivery(bool on);
    void retract(std::uint32_t sender, std::uint64_t serial);
    // True from a time advance request until its grant has been popped.
    bool time_advance_pending() const;
    // The lowest timestamp the sending rule allows now (-inf when not regulating).
    Time lowest_sendable_time() const;

    // ---- save/restore (HLA 1.3 §4.11-4.22; cpp/rti/client/save_restore.cpp, docs/save-restore.md) ----
    // The save and restore states change when their callbacks are popped. From initiateFederateSave until
    // federationSaved/NotSaved (and from federationRestoreBegun until federationRestored/NotRestored) the
    // services that change the federation's state raise SaveInProgress (RestoreInProgress).
    void request_federation_save(const std::string& label, const wire::OptionalTime& time);
    void federate_save_begun();
    void federate_save_complete(bool success);
    void request_federation_restore(const std::string& label);
    void federate_restore_complete(bool success);
    // IEEE 1516-2010: end the save or restore under way; every federate gets federationNotSaved or
    // federationNotRestored, aborted. The gateway raises SaveNotInProgress, RestoreNotInProgress.
    void abort_federation_save();
    void abort_federation_restore();
    // Why the last save or restore delivered failed (wire::SaveFailure, wire::RestoreFailure): for a front
    // end whose callback says why, as IEEE 1516-2010's do.
    std::uint8_t last_failure_reason() const;

    // ---- support services (local: answered from the FOM and what this federate knows) ----
    fom::Handle object_class_handle(const std::string& name) const;
    std::string object_class_name(fom::Handle cls) const;
    fom::Handle attribute_handle(const std::string& name, fom::Handle cls) const;
    std::string attribute_name(fom::Handle attribute, fom::Handle cls) const;
    fom::Handle interaction_class_handle(const std::string& name) const;
    std::string interaction_class_name(fom::Handle cls) const;
    fom::Handle parameter_handle(const std::string& name, fom::Handle cls) const;
    std::string parameter_name(fom::Handle parameter, fom::Handle cls) const;
    std::uint32_t object_instance_handle(const std::string& name) const;
    std::string object_instance_name(std::uint32_t object) const;
    fom::Handle object_class_of(std::uint32_t object) const;
    fom::Handle routing_space_handle(const std::string& name) const;
    std::string routing_space_name(fom::Handle space) const;
    fom::Handle dimension_handle(const std::string& name, fom::Handle space) const;
    std::string dimension_name(fom::Handle dimension, fom::Handle space) const;
    // An OMT module's dimension's upper bound (IEEE 1516-2010); 0 for a .fed's.
    std::uint64_t dimension_upper_bound(fom::Handle dimension, fom::Handle space) const;
    // IEEE 1516-2010's update rates: the FOM's rate named `designator` (InvalidUpdateRateDesignator), and the
    // rate this federate's subscription of a known object's class asked for (0: none).
    double update_rate(const std::string& designator) const;
    double update_rate_for(std::uint32_t object, fom::Handle attribute) const;
    fom::Handle attribute_routing_space(fom::Handle attribute, fom::Handle cls) const;
    std::set<fom::Handle> attribute_routing_spaces(fom::Handle cls) const;  // of all the class's attributes
    fom::Handle interaction_routing_space(fom::Handle cls) const;
    // The transportation and ordering types by name ("HLAreliable", "HLAbestEffort"; "Receive", "Timestamp")
    // and back, with CERTI's handles (fom::Transport, fom::Order); NameNotFound, InvalidTransportationHandle,
    // InvalidOrderingHandle.
    static std::uint8_t transportation_handle(const std::string& name);
    static std::string transportation_name(std::uint64_t handle);
    static std::uint8_t ordering_handle(const std::string& name);
    static std::string ordering_name(std::uint64_t handle);
    std::uint32_t federate_handle() const;
    // Why the connection is gone (IEEE 1516-2010's connectionLost); nullopt while it is up.
    std::optional<std::string> lost() const;
    bool closed() const { return closed_.load(); }  // lost() without its text: no lock, for every call
    TimeType time_type() const;  // the joined federation's

    // Messages sent and write system calls made so far (tests/transport/test_coalescing.py): a long run of sends
    // takes fewer writes than messages.
    struct SendCounts {
        std::uint64_t messages = 0;
        std::uint64_t writes = 0;
    };
    SendCounts send_counts() const { return {messages_sent_.load(), write_calls_.load()}; }

    // Held sends (RTIAmbassador.batch(), opt-in): while any hold is open, this federate's messages are kept
    // and written together, in one system call, when the last hold is released or before the next wait for
    // the gateway (a tick, a grant, an answer), whichever comes first; a batch over kMaxHeldBytes is written
    // at once. An update and the time advance request after it then cost the gateway one read.
    void hold_sends();
    void release_sends();

    // The gateway's state as JSON (needs no join), with the events of its log numbered above `events_after`,
    // and every object instance unless `instances` is false.
    std::string query_status(std::uint64_t events_after = 0, bool instances = true);

    // ---- the recorder federate (python -m hlacore.record, docs/record-replay.md) ----
    // Asks the gateway for the recording of this federate's federation and writes it into `path` (MCAP, the
    // same records as rtig --record) as it comes, until stop_recording(). Throws std::runtime_error when the
    // file cannot be created, RtiError when the gateway refuses.
    void start_recording(const std::string& path);
    // Closes the file, its summary written; returns the number of records. Throws std::runtime_error with the
    // write error that stopped the recording, if one did.
    std::uint64_t stop_recording();

    // ---- evoking callbacks ----
    // Reads what the socket has without blocking.
    void poll_now();
    // Waits until a callback is queued or the deadline passes; Interrupted when a signal arrived.
    WaitStatus wait_for_callback(Clock::time_point deadline);
    std::optional<wire::Message> pop_callback();
    // Whether callbacks are queued, or the last read left frames in the socket (it reads a batch at a time).
    bool has_callbacks() const;

private:
    // The proof of options.federation_secret for `action` on `federation`; empty when there is nothing to prove.
    std::string federation_proof(const char* action, const std::string& federation) const;
    // What this federate publishes and subscribes to without regions (client/declarations.cpp).
    struct DeclarationState {
        std::map<fom::Handle, std::set<fom::Handle>> published;   // object class -> attributes
        std::map<fom::Handle, std::set<fom::Handle>> subscribed;  // object class -> attributes
        std::set<fom::Handle> published_interactions;
        std::set<fom::Handle> subscribed_interactions;
        std::map<fom::Handle, double> rates;  // object class -> the update rate its subscription asks (IEEE 1516-2010)
        // HLA 4's directed interactions (client/directed.cpp): object class -> interaction classes.
        std::map<fom::Handle, std::set<fom::Handle>> published_directed;
        std::map<fom::Handle, std::set<fom::Handle>> subscribed_directed;  // received when owning an attribute
        std::map<fom::Handle, std::set<fom::Handle>> subscribed_directed_universally;
    };
    // ObjectClassNotDefined, InteractionClassNotDefined, a save or restore under way (client/directed.cpp).
    void check_directed(fom::Handle object_class, const std::vector<fom::Handle>& interactions) const;
    // Where this federate is in a federation save or restore (client/save_restore.cpp).
    struct SaveRestoreState {
        enum class SavePhase : std::uint8_t { None, Initiated, Begun, Answered };
        enum class RestorePhase : std::uint8_t { None, Begun, Initiated, Answered };
        SavePhase save = SavePhase::None;
        RestorePhase restore = RestorePhase::None;
        std::string label;  // of the save under way
        std::uint8_t failure = 0;  // why the last federationNotSaved or federationNotRestored delivered failed
    };
    using SavePhase = SaveRestoreState::SavePhase;
    using RestorePhase = SaveRestoreState::RestorePhase;
    struct TimeState {
        Time time = 0;
        Time lookahead = 0;
        // A lowered lookahead never allows a timestamp below one allowed before (HLA 1.3 §8.19).
        Time floor = -kInfinity;
        bool regulating = false;
        bool regulation_pending = false;
        bool constrained = false;
        bool constrained_pending = false;
        bool asynchronous_delivery = false;
        bool strict = false;  // the last grant kind counts as TAR/NER/FQR: with zero lookahead, sends must be > time
        Time enable_lookahead = 0;  // the highest lookahead since enableTimeRegulation, until it completes
        AdvanceKind pending = AdvanceKind::None;
        Time pending_time = 0;
        std::map<std::uint64_t, Time> retractable;  // own timestamped messages above the federate's time
    };

    struct LocalObject {
        fom::Handle object_class = 0;  // registered class, or the class it was discovered as
        std::string name;
        std::set<fom::Handle> owned;
        bool privilege_to_delete = false;
        // Ownership management (HLA 1.3 §7): the privilegeToDelete attribute (0 when the FOM has none:
        // then only the registrant may delete), attributes offered by negotiated divestiture, awaited by
        // attributeOwnershipAcquisition(IfAvailable), and those the RTI asked this federate to release.
        fom::Handle privilege_attribute = 0;
        std::map<fom::Handle, fom::Transport> transport;  // this federate's changes (HLA 1.3 §6.19), while it owns them
        std::set<fom::Handle> divesting;
        std::set<fom::Handle> acquiring;
        std::set<fom::Handle> acquiring_if_available;
        std::set<fom::Handle> release_requested;

        // The attribute becomes this federate's / stops being it: what was pending about it ends.
        void gain(fom::Handle a) {
            owned.insert(a);
            acquiring.erase(a);
            acquiring_if_available.erase(a);
            sync_privilege();
        }
        void lose(fom::Handle a) {
            owned.erase(a);
            transport.erase(a);  // the gateway forgets it too
            divesting.erase(a);
            release_requested.erase(a);
            sync_privilege();
        }
        void sync_privilege() {
            if (privilege_attribute) privilege_to_delete = owned.count(privilege_attribute) > 0;
        }
    };

    // Data distribution management state (client/regions.cpp), under mu_.
    struct LocalRegion {
        fom::Handle space = 0;
        wire::Handles bounds;  // lower, upper per dimension of the space, as sent to the gateway
    };
    struct DdmState {
        std::map<std::uint32_t, LocalRegion> regions;
        std::map<fom::Handle, std::map<std::uint32_t, std::set<fom::Handle>>> object_subscriptions;
        std::map<fom::Handle, std::set<std::uint32_t>> interaction_subscriptions;
        UpdateRegions update_regions;  // HLA 1.3: one region an attribute
    };
    const LocalRegion& known_region(std::uint32_t region) const;  // RegionNotKnown
    // RegionNotKnown, or InvalidRegionContext when the region is not in the class's routing space.
    void check_interaction_region(const fom::InteractionClass& c, std::uint32_t region) const;
    wire::Handles region_bounds(fom::Handle space, const Extent& extent) const;  // DimensionNotDefined, InvalidExtents
    // InvalidRegionContext unless the attribute's routing space is the region's.
    void check_region_space(const LocalRegion& region, const fom::ObjectClass& cls, fom::Handle attribute) const;
    bool region_in_use(std::uint32_t region) const;
    // initiateFederateRestore: the regions, region subscriptions and update associations as saved,
    // under their saved numbers (callers hold mu_).
    void restore_regions(const wire::RestoredState& saved);
    // After the FOM gained dimensions (FomExtended): each region spans the new ones whole, as the gateway's do.
    void widen_regions();
    // The FOM the gateway sent, in place of this federate's (mu_ held; a text that does not read closes the
    // connection: the gateway read it).
    void take_fom(const std::string& fed_text, const std::string& fed_name);
    void refuse_region_change_while_restoring(const char* service) const;  // RestoreInProgress

    // Encodes and writes one message (writer.cpp instantiates it for every message type).
    template <class M>
    void send(const M& message);
    // An update or interaction whose values all travel best effort, without a timestamp: as a datagram when
    // the path is up and it fits, else send() (client/datagrams.cpp).
    template <class M>
    void send_best_effort(const M& message);
    std::unique_lock<std::mutex> lock_send();
    // Coalescing (writer.cpp): a message sent within kDirectSends of the caller's last wait (a lone one, or
    // an update and its time advance request) is written by the caller at once; the rest of a longer run of
    // sends is appended to pending_ and written by the writer thread, many per system call while its
    // previous write is in flight (send_mu_ held for both). A write of less than kWriterLingerBelow bytes that
    // leaves nothing pending is followed by kWriterLinger of watching for more before the writer sleeps: in a
    // run of small sends the next batch then costs the caller no wake-up of the writer (docs/performance.md,
    // the lingering writer).
    static constexpr int kDirectSends = 4;
    static constexpr std::chrono::microseconds kWriterLinger{20};
    static constexpr std::size_t kWriterLingerBelow = 65536;
    static constexpr std::size_t kMaxPending = std::size_t{1} << 20;  // the caller then waits for room
    void send_encoded(std::unique_lock<std::mutex>& lock);  // send_buffer_'s message, in the stream's order
    void queue_send(std::unique_lock<std::mutex>& lock);
    void writer_loop();
    void write_bytes(const char* data, std::size_t size, WaitHost* host);
    // An update or interaction with a value of wire::kSplicedValueBytes or more, while nothing is queued:
    // written by the caller with sendmsg from the values where they are, around the rest encoded in
    // send_buffer_, rather than copied into it (a camera frame costs the kernel's copy only).
    template <class M>
    void send_spliced(const M& message);
    void write_pieces(iovec* pieces, std::size_t count, WaitHost* host);
    void check_frame_length(wire::MessageType type, std::size_t length);
    void require_member(wire::MessageType type) const;  // under send_mu_: FederateNotExecutionMember after a resign  // send_mu_, waiting for another thread's send with the host released
    void write_send_buffer();  // under send_mu_
    // The gateway is not reading (yet): waits with `host` (none on the writer thread) until it does.
    void wait_writable(std::size_t sent, WaitHost* host);
    void read_beside_send();
    // Sends a request and waits for its answer, a Result (HLACORE_ANSWERS; reader.cpp instantiates them). A
    // refusal raises its exception; an answer of another type closes the connection as a protocol error.
    template <class Result = wire::Reply>
    Result call(wire::Message request, std::uint32_t request_id);
    template <class Result = wire::Reply>
    Result await_reply(std::uint32_t request_id);
    wire::Message take_answer(std::uint32_t request_id);  // waits for it; raises a refusal
    std::uint32_t next_request();
    // Reads the socket until pred() holds (checked under mu_), the deadline passes or a signal arrives.
    template <class Pred>
    WaitStatus pump(Clock::time_point deadline, Pred pred);
    // What one read brought: frames from the stream, and best-effort messages from datagrams.
    struct Arrivals {
        std::vector<wire::Message> stream;
        std::vector<wire::Message> datagrams;
        std::optional<bool> more_in_socket;  // when the stream was read: whether the read stopped at a batch's end
        // Emptied for the next read, keeping the vectors' room (up to kKept messages): growing them again
        // moved each message once more on every read.
        void clear();
        static constexpr std::size_t kKept = 4096;
    };
    // What one read takes from the socket in small frames: about 3000 reflections of a small value, within kKept.
    static constexpr std::size_t kReadBatchBytes = 128u << 10;
    WaitStatus read_socket(Clock::time_point deadline, Arrivals& got);
    // A busy-polling spin that reads the stream as it polls (wait_readable): where it reads, and what the read
    // that found data returned, for read_socket's loop to take as its first read.
    struct SpinRead {
        char* into = nullptr;  // in_.room(want), made on the spin's first reading turn
        std::size_t want = 0;
        bool done = false;  // the spin read: `result` and `error` are that recv's
        ssize_t result = 0;
        int error = 0;
    };
    int wait_readable(pollfd* fds, nfds_t count, const timespec* timeout, bool& sliced, SpinRead* spin_read);
    void file(Arrivals& got);  // under mu_; clears got
    // The one receive dispatcher: file() visits each message onto arrived() once (true: a callback, queued),
    // pop_callback() each callback onto delivered() once. Overloads from HLACORE_CLIENT_ARRIVALS and
    // HLACORE_CLIENT_DELIVERIES in client/<group>.cpp; callers hold mu_.
    template <class M>
    bool arrived(M&) { return true; }
    template <class M>
    void delivered(const M&) {}
#define HLACORE_X(name) bool arrived(wire::name& m);
    HLACORE_CLIENT_ARRIVALS(HLACORE_X)
    HLACORE_ANSWERS(HLACORE_X)
#undef HLACORE_X
#define HLACORE_X(name) void delivered(const wire::name& m);
    HLACORE_CLIENT_DELIVERIES(HLACORE_X)
#undef HLACORE_X
    template <class Write>
    void write_recorded(Write write);  // a write into the recording; a failure stops it (client.cpp)
    // Best effort over UDP (client/datagrams.cpp): proving the path at connect (falling back to TCP with one
    // log line), reading what came, and whether an update or interaction may go as a datagram (mu_ held).
    void open_datagram_path(Clock::time_point deadline);
    void give_up_datagrams(const std::string& reason);
    void read_datagrams(std::vector<wire::Message>& got);
    bool best_effort(const LocalObject& obj, const wire::HandleValueViews& values) const;
    bool best_effort(fom::Handle interaction_class) const;
    // The reading thread's liveness step: when to look again, a Ping when the gateway has been silent for
    // half the timeout, GatewayNotResponding (the connection closed) after the whole timeout.
    Clock::time_point liveness_deadline() const;
    void check_liveness();
    // Closes the connection for `reason`: every later call raises `code` saying so.
    void close_connection(ErrorCode code, const std::string& reason);
    void close_locked(ErrorCode code, const std::string& reason);  // the same, mu_ held
    // A signal interrupted a wait: the host may abandon it, then the connection is closed when `owed`.
    void on_interrupt(const char* owed);
    // Waits until `done()` (under mu_) for an answer of the handshake kind, GatewayNotResponding at `deadline`.
    template <class Pred>
    void await_answer(Clock::time_point deadline, Pred done, const char* what);
    // The hlacore session on the connection: the Hello, the gateway's Welcome, the answer to its challenge.
    void open_session(Clock::time_point deadline);
    void authenticate(Clock::time_point deadline);
    // One SSL_write / SSL_read under ssl_mu_: bytes moved, 0 when the socket would block (WANT_READ/WRITE),
    // -1 with `error` (and `eof` for the end of the stream).
    long tls_write(const char* data, std::size_t length, std::string& error);
    long tls_read(char* data, std::size_t length, std::string& error);
    bool tls_pending();   // bytes in the session, decrypted or not (perhaps a record's start)
    bool tls_readable();  // decrypted bytes SSL_read would return at once
    ClockEstimate measure_clock(int probes);

    // The checks and the federate's own state change behind each of HLACORE_CLIENT_REQUESTS; callers hold mu_.
#define HLACORE_X(name) void check(const wire::name& m);
    HLACORE_CLIENT_REQUESTS(HLACORE_X)
#undef HLACORE_X
    // The checks behind the services; callers hold mu_.
    void require_joined() const;
    // ValueLengthExceeded unless `message` and what the gateway forwards of it fit the gateway's frame limit.
    template <class M>
    void check_forwardable(const M& message, const char* service) const {
        const std::size_t length = wire::frame_length(message) + wire::kForwardedGrowth;
        if (length > max_frame_bytes_) too_long(service, length);
    }
    [[noreturn]] void too_long(const char* service, std::size_t length) const;
    const fom::ObjectClass& defined_object_class(fom::Handle cls) const;
    const fom::UpdateRate& find_update_rate(const std::string& designator) const;  // InvalidUpdateRateDesignator
    const fom::Dimension& defined_dimension(fom::Handle dimension, fom::Handle space) const;
    // AttributeNotDefined for a handle the class does not have.
    static void check_attributes(const fom::ObjectClass& cls, const std::vector<fom::Handle>& attributes);
    // What sendInteraction checks before the time: the class is defined and published, the parameters defined.
    template <class Values>  // HandleValues or HandleValueViews
    const fom::InteractionClass& check_sendable(fom::Handle cls, const Values& values) const {
        const auto& c = defined_interaction_class(cls);
        if (!declarations_.published_interactions.count(cls))
            raise(ErrorCode::InteractionClassNotPublished, "interaction class '" + c.qualified_name + "' is not published");
        check_sendable_parameters(c, values);
        return c;
    }
    template <class Values>
    static void check_sendable_parameters(const fom::InteractionClass& c, const Values& values) {
        for (const auto& [param, value] : values) {
            if (!c.parameter(param))
                raise(ErrorCode::InteractionParameterNotDefined, "parameter handle " + std::to_string(param) +
                                                                     " is not defined for interaction '" +
                                                                     c.qualified_name + "'");
        }
    }
    const fom::InteractionClass& defined_interaction_class(fom::Handle cls) const;
    const LocalObject& known_object(std::uint32_t object) const;
    LocalObject& known_object(std::uint32_t object) {
        return const_cast<LocalObject&>(static_cast<const Client*>(this)->known_object(object));
    }
    // An object named in an ownership service, with its attributes checked (callers hold mu_).
    LocalObject& ownership_object(std::uint32_t object, const std::vector<fom::Handle>& attributes);
    LocalObject make_local_object(fom::Handle cls, const std::string& name) const;
    // An object the gateway registered for this federate, which owns `owned` and may delete it (mu_ held).
    void add_registered(std::uint32_t object, fom::Handle cls, const std::string& name, std::set<fom::Handle> owned);
    // The checks and message behind the transport and order changes (order, transport: 0 = unchanged).
    void change_attribute_delivery(std::uint32_t object, const std::vector<fom::Handle>& attributes,
                                   std::uint8_t order, std::uint8_t transport);
    void change_interaction_delivery(fom::Handle cls, std::uint8_t order, std::uint8_t transport);
    // Whether this federate publishes the attribute at the class it knows the object as; privilegeToDelete
    // counts as published with its class.
    bool publishes(const LocalObject& obj, fom::Handle attribute) const;
    // After publishing fewer attributes of `cls` (or none): the owned attributes of its instances that are
    // no longer published are divested unconditionally (HLA 1.3 §5.2-5.3); returns the messages to send.
    std::vector<wire::UnconditionalDivestiture> divest_unpublished(fom::Handle cls);
    [[noreturn]] void connection_lost() const;
    std::string lost_text() const;  // why, for connection_lost and lost()
    // Save/restore (client/save_restore.cpp; callers hold mu_): refuses `service` during a save or restore, and
    // applies the save/restore callbacks when popped (initiateFederateRestore replaces the mirrored state).
    void check_not_saving_or_restoring(const char* service) const;
    void require_idle(const char* service) const;  // require_joined, then check_not_saving_or_restoring
    void require_no_advance() const;                // TimeAdvanceAlreadyInProgress (client/time.cpp)
    // The lowest timestamp this federate may send now, and the checks of the sending rule (callers hold mu_).
    Time lowest_sendable() const;
    void check_send_time(const wire::OptionalTime& time) const;
    // Checks the sending rule for `time` and numbers the message (a timestamped one becomes retractable).
    std::uint64_t next_serial(const wire::OptionalTime& time);
    Time query_time(wire::TimeQuery which);  // the gateway's LBTS or minimum next event time

    std::string address_;
    ClientOptions options_;
    Clock::duration timeout_;
    int fd_ = -1;
    // With TLS: the session on fd_. OpenSSL's SSL object is not thread-safe and one thread may send while
    // another reads: each SSL_read and SSL_write runs under ssl_mu_ (never held while waiting).
    tls::Session ssl_;
    std::mutex ssl_mu_;

    std::mutex send_mu_;
    std::string send_buffer_;
    // The writer thread's state, under send_mu_: what it has yet to write, whether it is writing (then every
    // send queues behind it, keeping the stream's order) or asleep (then a send wakes it), its wake-up and the
    // callers' wait for room; and the count of messages queued, which the lingering writer watches unlocked.
    std::string pending_;
    bool writer_busy_ = false;
    bool writer_stop_ = false;
    bool writer_asleep_ = false;
    std::atomic<std::uint64_t> queued_{0};
    std::condition_variable writer_work_;
    std::condition_variable writer_room_;
    std::thread writer_;
    std::atomic<int> sends_since_wait_{0};  // reset by every read of the socket (pump)
    // Held sends (hold_sends), under send_mu_ but has_held_: the frames kept, how many, and the holds open.
    static constexpr std::size_t kMaxHeldBytes = 64 * 1024;
    std::string held_;
    std::uint64_t held_messages_ = 0;
    int holds_ = 0;
    std::atomic<bool> has_held_{false};  // read by every wait, which writes what is held
    void hold_encoded(std::unique_lock<std::mutex>& lock);  // send_buffer_'s message, kept
    void write_held(std::unique_lock<std::mutex>& lock);
    std::atomic<std::uint64_t> messages_sent_{0};
    std::atomic<std::uint64_t> write_calls_{0};
    bool member_ = false;  // under send_mu_: joined, and no resign sent since (federation_service() messages go)

    mutable std::mutex mu_;
    std::condition_variable cv_;
    bool reading_ = false;
    Arrivals arrivals_;  // the reading thread's (reading_), outside mu_ while it reads
    bool welcomed_ = false;
    std::atomic<bool> closed_{false};  // set under mu_ with its code and reason; read unlocked by a send
    ErrorCode closed_code_ = ErrorCode::RTIinternalError;
    std::string closed_reason_;
    std::string challenge_;                           // from the Welcome
    std::string nonce_;                               // from the Welcome: what federation proofs sign
    std::optional<wire::Authenticated> authenticated_;  // the gateway's answer to Authenticate
    std::optional<wire::ClockEcho> clock_echo_;        // the last answer to a ClockProbe
    std::uint32_t clock_probes_ = 0;
    std::mutex clock_mu_;  // one measurement at a time
    ClockEstimate clock_;
    bool clock_measured_ = false;  // under clock_mu_
    // The gateway's frame limit, from its Welcome (both directions).
    std::atomic<std::uint32_t> max_frame_bytes_{wire::kMaxFrameBytes};
    // Best effort over UDP: the socket (connected to the gateway's address), the token and size limit from
    // the Welcome, whether the path is up (set once at connect), the last sequence number sent (under
    // send_mu_), what came (the reading thread) and the counts (under datagram_mu_).
    int datagram_fd_ = -1;
    std::uint64_t datagram_token_ = 0;
    std::uint32_t max_datagram_ = 0;
    bool datagram_path_ = false;
    std::string datagram_reason_;
    std::uint64_t datagram_sequence_ = 0;
    std::string datagram_buffer_;  // under send_mu_
    wire::SequenceWindow datagram_window_;
    mutable std::mutex datagram_mu_;
    wire::DatagramStats datagram_stats_;
    std::map<fom::Handle, fom::Transport> interaction_transport_;  // this federate's changes (HLA 1.3 §6.20), under mu_
    // Touched only by the thread that is reading. Its blocks are kept for the connection's life (at most two
    // frame limits): a federate that was sent one camera frame is most often sent the next. The large values
    // of callbacks not delivered yet keep the blocks they lie in (wire::Value).
    wire::ReadBuffer in_;
    bool idle_after_spin_ = false;  // wait_readable(): a spin and the sleep after it found nothing
    std::uint64_t writes_before_spin_ = 0;  // write_calls_ when the last spin began
    Clock::time_point last_heard_;  // when the gateway last sent a byte
    Clock::time_point ping_sent_;   // when the unanswered Ping left (last_heard_ is later once answered)
    std::uint32_t pings_ = 0;
    std::atomic<std::uint64_t> heard_bytes_{0};  // every byte read, for a sender waiting on a full socket
    // Callbacks waiting for tick(), in arrival order: a vector consumed from the front and reused, so a
    // steady stream allocates nothing (a deque allocated a node per message once wire::Message grew to
    // 408 bytes with InitiateFederateRestore).
    class CallbackQueue {
    public:
        bool empty() const { return next_ == items_.size(); }
        void push(wire::Message&& m) { items_.push_back(std::move(m)); }
        // Takes all of `more`, leaving it empty; when the queue is empty, by swapping the vectors.
        void push_all(std::vector<wire::Message>& more) {
            if (empty()) {
                items_.clear();
                next_ = 0;
                items_.swap(more);
                return;
            }
            for (auto& m : more) items_.push_back(std::move(m));
            more.clear();
        }
        std::optional<wire::Message> pop() {
            std::optional<wire::Message> m(std::in_place, std::move(items_[next_++]));
            if (next_ == items_.size()) {
                items_.clear();
                next_ = 0;
            } else if (next_ >= 1024 && next_ * 2 >= items_.size()) {  // never drained: drop the spent front
                items_.erase(items_.begin(), items_.begin() + static_cast<std::ptrdiff_t>(next_));
                next_ = 0;
            }
            return m;
        }

    private:
        std::vector<wire::Message> items_;
        std::size_t next_ = 0;
    };
    CallbackQueue callbacks_;
    bool more_in_socket_ = false;  // the last read of the stream left frames in the socket (kReadBatchBytes)
    std::map<std::uint32_t, wire::Message> replies_;  // the answers (HLACORE_ANSWERS) by request id
    std::uint32_t last_request_ = 0;

    // Federate state, under mu_. The FOM is replaced whole when another federate extends it at join (every
    // reader holds mu_, so none sees it change under it).
    std::unique_ptr<fom::Fom> fom_;
    // A FomExtended filed between this federate's FederationJoined and join() taking that FOM: the later one.
    std::optional<wire::FomExtended> early_fom_;
    std::uint32_t federate_ = 0;
    TimeType time_type_ = TimeType::Float64;
    // One piece of state per service group, each changed in client/<group>.cpp.
    std::set<std::string> announced_;  // sync_points: the labels announced and not yet synchronized
    std::unique_ptr<mcap::Writer> recording_;  // written as Recorded messages come, under mu_
    std::string recording_failure_;
    DeclarationState declarations_;
    std::unordered_map<std::uint32_t, LocalObject> objects_;  // objects, with their ownership
    std::uint64_t serial_ = 0;                                // objects: the last message serial
    TimeState time_;
    SaveRestoreState save_restore_;
    DdmState ddm_;  // regions
};

}  // namespace hlacore
