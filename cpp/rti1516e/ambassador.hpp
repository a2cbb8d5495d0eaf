// The inside of librti1516e: hlacore's RTIambassador (IEEE 1516.1-2010's services over hlacore's federate side,
// as hlacore.rti1516e serves them in Python), the handles as the client's numbers, and the errors of the core
// as the standard's exceptions. Not installed.
#pragma once

#include <RTI/FederateAmbassador.h>
#include <RTI/RTIambassador.h>
#include <RTI/time/HLAtimeTypes.h>

#include <atomic>
#include <condition_variable>
#include <cstring>
#include <type_traits>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "rti/client/client.hpp"
#include "rti/client/guarded.hpp"
#include "rti/wire/json_value.hpp"
#include "rti1516e/text.hpp"

// What the library knows of a handle: the friend each handle class names.
#define HLACORE_HANDLE_FRIEND(Kind)                                                                   \
    class Kind##Friend {                                                                              \
    public:                                                                                           \
        static Kind make(unsigned long long value, unsigned long sender = 0) {                        \
            Kind h;                                                                                   \
            h._value = value;                                                                         \
            h._sender = sender;                                                                       \
            h._valid = true;                                                                          \
            return h;                                                                                 \
        }                                                                                             \
        static unsigned long long value(Kind const& h) { return h._valid ? h._value : 0; }            \
        static unsigned long sender(Kind const& h) { return h._sender; }                              \
    };
namespace rti1516e {
RTI1516E_HANDLE_KINDS(HLACORE_HANDLE_FRIEND)
}  // namespace rti1516e
#undef HLACORE_HANDLE_FRIEND

namespace hlacore::rti1516e {

namespace api = ::rti1516e;
// The services' declarations (RTI1516E_SERVICES) name the API's types unqualified.
using namespace ::rti1516e;

template <class H>
struct FriendOf;
#define HLACORE_X(Kind)                    \
    template <>                            \
    struct FriendOf<api::Kind> {           \
        using type = api::Kind##Friend;    \
    };
RTI1516E_HANDLE_KINDS(HLACORE_X)
#undef HLACORE_X

// A handle from the client's number, and back (an invalid handle is 0, which names nothing in the core).
template <class H>
H handle(unsigned long long value) {
    return FriendOf<H>::type::make(value);
}
template <class H>
std::uint32_t core(H const& h) {
    const unsigned long long v = FriendOf<H>::type::value(h);
    return v > 0xFFFFFFFEull ? 0xFFFFFFFFu : static_cast<std::uint32_t>(v);
}
template <class H>
wire::Handles cores(std::set<H> const& set) {
    wire::Handles out;
    out.reserve(set.size());
    for (const H& h : set) out.push_back(core(h));
    return out;
}
template <class H, class Numbers>
std::set<H> handles(Numbers const& numbers) {
    std::set<H> out;
    for (auto n : numbers) out.insert(handle<H>(n));
    return out;
}
inline api::MessageRetractionHandle retraction(std::uint32_t sender, std::uint64_t serial) {
    return api::MessageRetractionHandleFriend::make(serial, sender);
}

// An enumeration's value as the federate gave it, read without assuming it is one of the enumerators: any number
// may be cast to the type, and loading one outside its range as the enumeration is undefined behaviour.
template <class E>
long long raw(E const& e) {
    std::underlying_type_t<E> v;
    std::memcpy(&v, &e, sizeof v);
    return static_cast<long long>(v);
}

std::string bytes(api::VariableLengthData const& data);  // a tag
wire::HandleValues copies(api::ParameterHandleValueMap const& values);  // values the client keeps (objects.cpp)

// Translates the exception being handled into the IEEE 1516-2010 exception of the same meaning (the core's
// names that the standard renames, RTIinternalError for the rest); one of the API's goes through unchanged.
[[noreturn]] void rethrow_as_1516e();
// The exception named `name` (RTI1516E_EXCEPTIONS), carrying `reason`.
[[noreturn]] void raise(std::string const& name, std::string const& reason);
// The RTIinternalError of what hlacore does not serve yet, saying why (as hlacore.rti1516e words it).
[[noreturn]] void not_served(std::string const& what, std::string const& why);

template <class F>
auto guarded(F&& service) -> decltype(service()) {
    return guarded_by(rethrow_as_1516e, std::forward<F>(service));
}

// The core's time as the federation's time type, made where it is used (a callback's time costs no
// allocation): an HLAinteger64Time federation's times are whole numbers of the core's doubles.
class TimeOut {
public:
    explicit TimeOut(bool integer) : integer_(integer) {}
    api::LogicalTime const& operator()(double time);

private:
    bool integer_;
    api::HLAfloat64Time float_;
    api::HLAinteger64Time integer_time_;
};

// HLA 4's set of interaction classes, which IEEE 1516-2010's API has no name for.
using InteractionClassHandleSet = std::set<api::InteractionClassHandle>;

// Not of IEEE 1516-2010: HLA 4's directed interactions (IEEE 1516.1-2025 §6.15) for the Federate Protocol's door,
// whose federate ambassador is also one of these (the ambassador delivers them to no other).
class DirectedInteractionReceiver {
public:
    virtual ~DirectedInteractionReceiver() = default;
    virtual void receiveDirectedInteraction(api::InteractionClassHandle cls, api::ObjectInstanceHandle object,
                                            api::ParameterHandleValueMap const& values, api::VariableLengthData const& tag,
                                            api::TransportationType transport, api::FederateHandle producer) = 0;
    // Timestamped: `retraction` null when it cannot be retracted.
    virtual void receiveDirectedInteraction(api::InteractionClassHandle cls, api::ObjectInstanceHandle object,
                                            api::ParameterHandleValueMap const& values, api::VariableLengthData const& tag,
                                            api::TransportationType transport, api::FederateHandle producer,
                                            api::LogicalTime const& time, api::OrderType sent, api::OrderType received,
                                            api::MessageRetractionHandle const* retraction) = 0;
};

class Ambassador final : public api::RTIambassador {
public:
    Ambassador() = default;
    ~Ambassador() override;
#define HLACORE_X(ret, name, params, qualifier) ret name params qualifier override;
    RTI1516E_SERVICES(HLACORE_X)
#undef HLACORE_X

    // Delivers one callback (callbacks.cpp): the layer's own first, then the gateway's. False when none was queued.
    bool deliver_one();
    // Not of IEEE 1516-2010: HLA 4's listFederationExecutionMembers, for the Federate Protocol's door. Each federate
    // of `federation` as (name, type), from the gateway's report; false when there is no such federation.
    bool federationMembers(std::wstring const& federation, std::vector<std::pair<std::wstring, std::wstring>>& members);
    // Not of IEEE 1516-2010: HLA 4's getAvailableDimensionsForObjectClass (regions.cpp), for the same door: the
    // dimensions of any of the class's attributes.
    DimensionHandleSet availableDimensionsForObjectClass(ObjectClassHandle cls);
    // Not of IEEE 1516-2010: HLA 4's directed interactions (directed.cpp; IEEE 1516.1-2025 §5.6-5.13, §6.14), for
    // the same door. An unpublish or unsubscribe without interaction classes is of all the object class's.
    void publishObjectClassDirectedInteractions(api::ObjectClassHandle cls, InteractionClassHandleSet const& interactions);
    void unpublishObjectClassDirectedInteractions(api::ObjectClassHandle cls);
    void unpublishObjectClassDirectedInteractions(api::ObjectClassHandle cls,
                                                  InteractionClassHandleSet const& interactions);
    void subscribeObjectClassDirectedInteractions(api::ObjectClassHandle cls,
                                                  InteractionClassHandleSet const& interactions, bool universally);
    void unsubscribeObjectClassDirectedInteractions(api::ObjectClassHandle cls);
    void unsubscribeObjectClassDirectedInteractions(api::ObjectClassHandle cls,
                                                    InteractionClassHandleSet const& interactions);
    void sendDirectedInteraction(api::InteractionClassHandle cls, api::ObjectInstanceHandle object,
                                 api::ParameterHandleValueMap const& values, api::VariableLengthData const& tag);
    api::MessageRetractionHandle sendDirectedInteraction(api::InteractionClassHandle cls, api::ObjectInstanceHandle object,
                                                         api::ParameterHandleValueMap const& values,
                                                         api::VariableLengthData const& tag, api::LogicalTime const& time);

private:
    Client& client() const;  // NotConnected
    double time_in(api::LogicalTime const& time) const;  // InvalidLogicalTime for another type
    double interval_in(api::LogicalTimeInterval const& interval) const;
    // Publications and subscriptions add up in 1516-2010, and replace each other in the core.
    using Declared = std::map<std::uint32_t, std::set<std::uint32_t>>;
    void declare(Declared& table, api::ObjectClassHandle cls, api::AttributeHandleSet const& attributes, bool adding,
                 bool publishing, bool active = true);
    void require_reserved(std::wstring const& name) const;  // ObjectInstanceNameNotReserved
    // The gateway's status report (support.cpp), and this federate's federation in it.
    JsonValue report() const;
    JsonValue federation() const;
    template <class Status, class Answer>
    void answer_statuses(Status status, Answer answer);
    void stop_immediate();
    void deliver(wire::Message& message);

    std::unique_ptr<Client> client_;
    api::FederateAmbassador* federate_ = nullptr;
    DirectedInteractionReceiver* directed_ = nullptr;  // federate_, when it receives HLA 4's directed interactions
    bool immediate_ = false;
    bool joined_ = false;
    bool integer_time_ = false;
    std::string federate_name_;
    Declared published_, subscribed_;
    api::ResignAction resign_directive_ = api::CANCEL_THEN_DELETE_THEN_DIVEST;

    // What callbacks need of the calls before them, and the callbacks this layer makes itself.
    mutable std::recursive_mutex mu_;
    std::deque<std::function<void(api::FederateAmbassador&)>> local_;
    std::map<std::string, bool> sync_sets_;                // label -> registered with a federate set
    std::set<std::wstring> reserved_;                      // names reserved and not used yet
    std::map<std::uint32_t, std::set<std::uint32_t>> divesting_;      // object -> attributes to confirm
    std::map<std::uint32_t, std::set<std::uint32_t>> release_asked_;  // object -> attributes another asked for
    bool callbacks_enabled_ = true;
    bool saving_ = false;

    // Regions (regions.cpp): each one's ranges [lower, upper) by dimension, set until committed.
    std::map<std::uint32_t, std::map<std::uint32_t, api::RangeBounds>> regions_;
    std::uint32_t space() const;  // the FOM modules' dimensions' routing space
    std::map<std::uint32_t, api::RangeBounds>& region(api::RegionHandle const& r);
    Client::Extent extent(std::map<std::uint32_t, api::RangeBounds> const& ranges) const;
    // Each (attributes, region) of the pairs, a region of this federate's (RegionNotCreatedByThisFederate).
    std::vector<std::pair<wire::Handles, std::uint32_t>> region_pairs(
        api::AttributeHandleSetRegionHandleSetPairVector const& pairs);
    wire::Handles regions_of(api::RegionHandleSet const& regions);  // the same for a set of regions
    api::DimensionHandleSet dimensions_of(std::uint32_t space_handle) const;

    // HLA_IMMEDIATE: a thread of the ambassador's delivers the callbacks as they arrive.
    std::thread immediate_thread_;
    std::atomic<bool> stop_{false};
};

}  // namespace hlacore::rti1516e
