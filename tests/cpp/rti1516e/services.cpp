// Every service of the IEEE 1516-2010 C++ API (each entry of RTI1516E_SERVICES, overloads apart) called at
// least once through a gateway, each with an asserted outcome: the callbacks it brings with their arguments,
// what it returns, a state seen later, or the exception it must raise (a bad argument's, or RTIinternalError
// "hlacore does not serve ... yet" for what it does not serve). Two evoked federates in an HLAfloat64Time federation,
// and an HLA_IMMEDIATE one in an HLAinteger64Time federation, which a fourth joins adding a FOM module.
// Usage: rti1516e_services VEHICLES_XML CARS_XML [ADDRESS] (no address: $HLACORE_RTIG). Prints
// "called N services", N the entries called; tests/rti/test_rti1516e_cpp_services.py runs it.
#include <RTI/RTI1516.h>
#include <RTI/time/HLAfloat64Interval.h>
#include <RTI/time/HLAfloat64Time.h>
#include <RTI/time/HLAinteger64Interval.h>
#include <RTI/time/HLAinteger64Time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "../check.hh"

using namespace rti1516e;

// ---- which entries of RTI1516E_SERVICES were called ----

// A twin of each entry, declared only: overload resolution on a call's arguments (in decltype, so they are
// not evaluated twice) picks the same entry as on the ambassador, and its type names the entry.
template <int N>
struct Entry {
    static constexpr int index = N;
};
constexpr int kFirst = __COUNTER__ + 1;
namespace twin {
#define TWIN(ret, name, params, qualifier) Entry<__COUNTER__ - kFirst> name params;
RTI1516E_SERVICES(TWIN)
#undef TWIN
}  // namespace twin
constexpr int kEntries = __COUNTER__ - kFirst;

namespace {

#define NAME_OF(ret, name, params, qualifier) #name,
const char* const kNames[] = {RTI1516E_SERVICES(NAME_OF)};
#undef NAME_OF
static_assert(sizeof(kNames) / sizeof(kNames[0]) == kEntries, "one twin an entry");

std::set<int> called;
template <int N>
void note() {
    called.insert(N);
}

// Calls a service of a federate's ambassador, noting its entry.
#define CALL(fed, service, ...) \
    (note<decltype(twin::service(__VA_ARGS__))::index>(), (fed).rti->service(__VA_ARGS__))

// ---- the callbacks' arguments as text ----

std::wstring wide(std::string const& s) { return std::wstring(s.begin(), s.end()); }
std::wstring show(std::wstring const& s) { return s; }
std::wstring show(wchar_t const* s) { return s; }
std::wstring show(int v) { return std::to_wstring(v); }
template <class T>
auto show(T const& value) -> decltype(value.toString()) {  // handles, times
    return value.toString();
}
std::wstring show(VariableLengthData const& d) {
    return wide(std::string(static_cast<char const*>(d.data()), d.size()));
}
template <class T>
std::wstring show(std::set<T> const& items) {
    std::wstring out = L"{";
    for (auto const& i : items) out += (out.size() > 1 ? L"," : L"") + show(i);
    return out + L"}";
}
template <class K>
std::wstring show(std::map<K, VariableLengthData> const& values) {
    std::wstring out = L"{";
    for (auto const& [h, v] : values) out += (out.size() > 1 ? L"," : L"") + show(h) + L"=" + show(v);
    return out + L"}";
}
template <class Info>  // the supplemental information of a reflection, an interaction or a removal
auto show(Info const& info) -> decltype(info.producingFederate, std::wstring()) {
    return info.hasProducingFederate ? L"from " + info.producingFederate.toString() : L"-";
}
// The status services' answers: each federation's name and time type; each federate's save or restore status.
std::wstring show(FederationExecutionInformationVector const& federations) {
    std::wstring out;
    for (auto const& f : federations) out += f.federationExecutionName + L":" + f.logicalTimeImplementationName + L";";
    return out;
}
std::wstring show(FederateHandleSaveStatusPairVector const& statuses) {
    std::wstring out;
    for (auto const& [h, status] : statuses) out += h.toString() + L"=" + std::to_wstring(status) + L";";
    return out;
}
std::wstring show(FederateRestoreStatusVector const& statuses) {
    std::wstring out;
    for (auto const& s : statuses)
        out += s.preRestoreHandle.toString() + L">" + s.postRestoreHandle.toString() + L"=" + std::to_wstring(s.status) + L";";
    return out;
}
template <class... A>
std::wstring text(A const&... args) {
    std::wstring out;
    ((out += L"|" + show(args)), ...);
    return out.empty() ? out : out.substr(1);
}

// Records every callback it gets, by name with its arguments as text (also from HLA_IMMEDIATE's thread).
struct Recorder : NullFederateAmbassador {
    mutable std::mutex mu;
    std::vector<std::pair<std::string, std::wstring>> events;

    template <class... A>
    void note(const char* name, A const&... args) {
        std::lock_guard<std::mutex> lock(mu);
        events.emplace_back(name, text(args...));
    }
    size_t count(std::string const& name) const {
        std::lock_guard<std::mutex> lock(mu);
        return std::count_if(events.begin(), events.end(), [&](auto const& e) { return e.first == name; });
    }
    bool has(std::string const& name, std::wstring const& args) const {
        std::lock_guard<std::mutex> lock(mu);
        return std::find(events.begin(), events.end(), std::make_pair(name, args)) != events.end();
    }
    // Whether a `name` came whose arguments hold `part`.
    bool seen(std::string const& name, std::wstring const& part) const {
        std::lock_guard<std::mutex> lock(mu);
        return std::any_of(events.begin(), events.end(), [&](auto const& e) {
            return e.first == name && e.second.find(part) != std::wstring::npos;
        });
    }
    // The arguments of each `name` in order.
    std::vector<std::wstring> all(std::string const& name) const {
        std::lock_guard<std::mutex> lock(mu);
        std::vector<std::wstring> out;
        for (auto const& e : events)
            if (e.first == name) out.push_back(e.second);
        return out;
    }
    size_t size() const {
        std::lock_guard<std::mutex> lock(mu);
        return events.size();
    }

#define RECORD(name, params, ...) \
    void name params override { note(#name, __VA_ARGS__); }
    RECORD(connectionLost, (std::wstring const& fault), fault)
    RECORD(reportFederationExecutions, (FederationExecutionInformationVector const& federations), federations)
    RECORD(federationSaveStatusResponse, (FederateHandleSaveStatusPairVector const& statuses), statuses)
    RECORD(federationRestoreStatusResponse, (FederateRestoreStatusVector const& statuses), statuses)
    RECORD(synchronizationPointRegistrationSucceeded, (std::wstring const& label), label)
    RECORD(synchronizationPointRegistrationFailed, (std::wstring const& label, SynchronizationPointFailureReason r),
           label, r)
    RECORD(announceSynchronizationPoint, (std::wstring const& label, VariableLengthData const& tag), label, tag)
    RECORD(federationSynchronized, (std::wstring const& label, FederateHandleSet const& failed), label, failed)
    RECORD(initiateFederateSave, (std::wstring const& label), label)
    RECORD(initiateFederateSave, (std::wstring const& label, LogicalTime const& time), label, time)
    RECORD(federationSaved, (), L"")
    RECORD(federationNotSaved, (SaveFailureReason reason), reason)
    RECORD(requestFederationRestoreSucceeded, (std::wstring const& label), label)
    RECORD(requestFederationRestoreFailed, (std::wstring const& label), label)
    RECORD(federationRestoreBegun, (), L"")
    RECORD(initiateFederateRestore, (std::wstring const& label, std::wstring const& name, FederateHandle h), label,
           name, h)
    RECORD(federationRestored, (), L"")
    RECORD(federationNotRestored, (RestoreFailureReason reason), reason)
    RECORD(startRegistrationForObjectClass, (ObjectClassHandle cls), cls)
    RECORD(stopRegistrationForObjectClass, (ObjectClassHandle cls), cls)
    RECORD(turnInteractionsOn, (InteractionClassHandle cls), cls)
    RECORD(turnInteractionsOff, (InteractionClassHandle cls), cls)
    RECORD(objectInstanceNameReservationSucceeded, (std::wstring const& name), name)
    RECORD(objectInstanceNameReservationFailed, (std::wstring const& name), name)
    RECORD(multipleObjectInstanceNameReservationSucceeded, (std::set<std::wstring> const& names), names)
    RECORD(multipleObjectInstanceNameReservationFailed, (std::set<std::wstring> const& names), names)
    RECORD(discoverObjectInstance, (ObjectInstanceHandle o, ObjectClassHandle c, std::wstring const& n), o, c, n)
// A reflection's or an interaction's two overloads that hlacore calls: receive order, timestamped.
#define VALUES(name, Target, Values, Info)                                                                       \
    RECORD(name, (Target o, Values const& v, VariableLengthData const& tag, OrderType sent, TransportationType t, \
           Info info), o, v, tag, sent, t, info)                                                                 \
    RECORD(name, (Target o, Values const& v, VariableLengthData const& tag, OrderType sent, TransportationType t, \
           LogicalTime const& time, OrderType received, MessageRetractionHandle h, Info info),                  \
           o, v, tag, sent, t, time, received, h, info)
    VALUES(reflectAttributeValues, ObjectInstanceHandle, AttributeHandleValueMap, SupplementalReflectInfo)
    VALUES(receiveInteraction, InteractionClassHandle, ParameterHandleValueMap, SupplementalReceiveInfo)
#undef VALUES
    RECORD(removeObjectInstance, (ObjectInstanceHandle o, VariableLengthData const& tag, OrderType sent,
           SupplementalRemoveInfo info), o, tag, sent, info)
    RECORD(removeObjectInstance, (ObjectInstanceHandle o, VariableLengthData const& tag, OrderType sent,
           LogicalTime const& time, OrderType received, MessageRetractionHandle h, SupplementalRemoveInfo info),
           o, tag, sent, time, received, h, info)
    RECORD(attributesInScope, (ObjectInstanceHandle o, AttributeHandleSet const& a), o, a)
    RECORD(attributesOutOfScope, (ObjectInstanceHandle o, AttributeHandleSet const& a), o, a)
    RECORD(provideAttributeValueUpdate, (ObjectInstanceHandle o, AttributeHandleSet const& a,
           VariableLengthData const& tag), o, a, tag)
    RECORD(turnUpdatesOnForObjectInstance, (ObjectInstanceHandle o, AttributeHandleSet const& a), o, a)
    RECORD(turnUpdatesOffForObjectInstance, (ObjectInstanceHandle o, AttributeHandleSet const& a), o, a)
    RECORD(confirmAttributeTransportationTypeChange, (ObjectInstanceHandle o, AttributeHandleSet a,
           TransportationType t), o, a, t)
    RECORD(confirmInteractionTransportationTypeChange, (InteractionClassHandle c, TransportationType t), c, t)
    RECORD(reportAttributeTransportationType, (ObjectInstanceHandle o, AttributeHandle a, TransportationType t), o, a, t)
    RECORD(reportInteractionTransportationType, (FederateHandle f, InteractionClassHandle c, TransportationType t), f, c, t)
    RECORD(requestAttributeOwnershipAssumption, (ObjectInstanceHandle o, AttributeHandleSet const& a,
           VariableLengthData const& tag), o, a, tag)
    RECORD(requestDivestitureConfirmation, (ObjectInstanceHandle o, AttributeHandleSet const& a), o, a)
    RECORD(attributeOwnershipAcquisitionNotification, (ObjectInstanceHandle o, AttributeHandleSet const& a,
           VariableLengthData const& tag), o, a, tag)
    RECORD(requestAttributeOwnershipRelease, (ObjectInstanceHandle o, AttributeHandleSet const& a,
           VariableLengthData const& tag), o, a, tag)
    RECORD(confirmAttributeOwnershipAcquisitionCancellation, (ObjectInstanceHandle o, AttributeHandleSet const& a),
           o, a)
    RECORD(informAttributeOwnership, (ObjectInstanceHandle o, AttributeHandle a, FederateHandle owner), o, a, owner)
    RECORD(attributeIsNotOwned, (ObjectInstanceHandle o, AttributeHandle a), o, a)
    RECORD(timeRegulationEnabled, (LogicalTime const& time), time)
    RECORD(timeConstrainedEnabled, (LogicalTime const& time), time)
    RECORD(timeAdvanceGrant, (LogicalTime const& time), time)
    RECORD(requestRetraction, (MessageRetractionHandle h), h)
#undef RECORD
};

struct Federate {
    explicit Federate(const char* name) : label(name) {}
    const char* label;
    Recorder rec;
    std::unique_ptr<RTIambassador> rti = RTIambassadorFactory().createRTIambassador();
    bool evoked = true;
};

std::vector<Federate*> everyone;  // for the events shown when a check fails (CHECK exits)

void show_events() {
    for (Federate* f : everyone) {
        std::lock_guard<std::mutex> lock(f->rec.mu);
        const auto& e = f->rec.events;
        std::fprintf(stderr, "%s's last callbacks:\n", f->label);
        for (size_t i = e.size() > 12 ? e.size() - 12 : 0; i < e.size(); ++i)
            std::fprintf(stderr, "  %s(%ls)\n", e[i].first.c_str(), e[i].second.c_str());
    }
}

// Delivers the federates' callbacks (an immediate federate's come by themselves) until `done`.
void until(std::initializer_list<Federate*> feds, std::function<bool()> done, const char* what) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!done()) {
        if (std::chrono::steady_clock::now() > deadline) {
            std::fprintf(stderr, "timed out waiting for %s\n", what);
            std::exit(1);
        }
        for (Federate* f : feds) {
            if (f->evoked) CALL(*f, evokeMultipleCallbacks, 0.01, 0.05);
            else std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
    }
}

// Waits for `name` with these arguments at `f`.
void await(Federate& f, std::string const& name, std::wstring const& args) {
    until({&f}, [&] { return f.rec.has(name, args); }, name.c_str());
}

// Runs `call`, which must raise E (whose text holds `says`).
template <class E>
bool raises(std::function<void()> call, std::wstring const& says = L"") {
    try {
        call();
    } catch (E const& e) {
        return e.what().find(says) != std::wstring::npos;
    }
    return false;
}
bool not_served(std::function<void()> call) { return raises<RTIinternalError>(call, L"hlacore does not serve"); }

// Everything the gateway had sent to each federate before now, delivered: a round trip each (a request
// with an answer, whose answer comes after what the gateway sent before it), in order, then its callbacks.
void settle(std::initializer_list<Federate*> feds) {
    for (Federate* f : feds) {
        CHECK(raises<FederationExecutionDoesNotExist>([&] { f->rti->destroyFederationExecution(L"no-such"); }));
        while (CALL(*f, evokeMultipleCallbacks, 0.0, 0.05)) {
        }
    }
}

std::pair<unsigned long, unsigned long> bounds(RangeBounds const& r) { return {r.getLowerBound(), r.getUpperBound()}; }
VariableLengthData data(const char* s) { return VariableLengthData(s, std::strlen(s)); }
HLAfloat64Time at(double t) { return HLAfloat64Time(t); }
AttributeHandleSetRegionHandleSetPairVector in(AttributeHandleSet const& attributes, RegionHandleSet const& regions) {
    return {{attributes, regions}};
}

// The handles and names the scenario shares.
struct World {
    Federate a{"a"}, b{"b"}, c{"c"};
    std::wstring address;
    FederateHandle ha, hb;
    ObjectClassHandle vehicle, car;
    AttributeHandle position, speed, doors;
    InteractionClassHandle command;
    ParameterHandle verb;
    DimensionHandle x, y;
    ObjectInstanceHandle v1, v2, v3, v4;
};

// The supplemental information of what a sent: C++ names the producing federate of every message (Python
// only of timestamped ones).
std::wstring from(World const& w) { return L"from " + w.ha.toString(); }

// ---- federation management: connecting, creating, joining (§4.2-4.9) ----
void connect_create_join(World& w, std::wstring const& vehicles, std::wstring const& cars) {
    Federate& a = w.a;
    Federate& b = w.b;
    CALL(a, connect, a.rec, HLA_EVOKED, w.address);
    CHECK(raises<AlreadyConnected>([&] { CALL(a, connect, a.rec, HLA_EVOKED, w.address); }));
    Federate odd{"odd"};
    CHECK(raises<UnsupportedCallbackModel>([&] { CALL(odd, connect, odd.rec, static_cast<CallbackModel>(7)); }));
    b.rti->connect(b.rec, HLA_EVOKED, w.address);
    CALL(a, createFederationExecution, L"Services", std::vector<std::wstring>{vehicles, cars});
    CHECK(raises<FederationExecutionAlreadyExists>([&] { CALL(a, createFederationExecution, L"Services", vehicles); }));
    CHECK(raises<CouldNotCreateLogicalTimeFactory>([&] { a.rti->createFederationExecution(L"T", vehicles, L"HLAfloat32Time"); }));
    // With a MIM (merged first: here the Vehicles module under the Cars one): created, then destroyed.
    CALL(a, createFederationExecutionWithMIM, L"WithMIM", std::vector<std::wstring>{cars}, vehicles);
    CHECK(raises<FederationExecutionAlreadyExists>([&] { a.rti->createFederationExecution(L"WithMIM", cars); }));
    CALL(a, destroyFederationExecution, L"WithMIM");
    CHECK(raises<FederationExecutionDoesNotExist>([&] { a.rti->destroyFederationExecution(L"WithMIM"); }));
    CALL(a, listFederationExecutions);
    await(a, "reportFederationExecutions", L"Services:HLAfloat64Time;");
    w.ha = CALL(a, joinFederationExecution, L"a", L"test", L"Services");
    w.hb = b.rti->joinFederationExecution(L"b", L"test", L"Services");
    CHECK(w.ha.isValid() && w.hb.isValid() && w.ha != w.hb);
    CHECK(raises<FederateAlreadyExecutionMember>([&] { a.rti->joinFederationExecution(L"a2", L"test", L"Services"); }));
}

// ---- support services (§10) ----
void support(World& w) {
    Federate& a = w.a;
    w.vehicle = CALL(a, getObjectClassHandle, L"Vehicle");
    CHECK(CALL(a, getObjectClassName, w.vehicle) == L"Vehicle");
    w.car = a.rti->getObjectClassHandle(L"HLAobjectRoot.Vehicle.Car");  // from the second module
    CHECK(raises<NameNotFound>([&] { a.rti->getObjectClassHandle(L"Spaceship"); }));
    w.position = CALL(a, getAttributeHandle, w.vehicle, L"position");
    w.speed = a.rti->getAttributeHandle(w.vehicle, L"speed");
    w.doors = a.rti->getAttributeHandle(w.car, L"doors");
    CHECK(CALL(a, getAttributeName, w.vehicle, w.speed) == L"speed");
    w.command = CALL(a, getInteractionClassHandle, L"Command");
    CHECK(CALL(a, getInteractionClassName, w.command) == L"Command");
    w.verb = CALL(a, getParameterHandle, w.command, L"verb");
    CHECK(CALL(a, getParameterName, w.command, w.verb) == L"verb");
    CHECK(CALL(a, getOrderType, L"TimeStamp") == TIMESTAMP && CALL(a, getOrderName, RECEIVE) == L"Receive");
    CHECK(raises<InvalidOrderName>([&] { a.rti->getOrderType(L"Sometime"); }));
    CHECK(CALL(a, getTransportationType, L"HLAbestEffort") == BEST_EFFORT);
    CHECK(CALL(a, getTransportationName, RELIABLE) == L"HLAreliable");
    CHECK(raises<InvalidTransportationName>([&] { a.rti->getTransportationType(L"HLAcarrierPigeon"); }));
    w.x = CALL(a, getDimensionHandle, L"X");
    w.y = a.rti->getDimensionHandle(L"Y");
    CHECK(CALL(a, getDimensionName, w.y) == L"Y");
    CHECK(CALL(a, getDimensionUpperBound, w.x) == 1000 && a.rti->getDimensionUpperBound(w.y) == 500);
    CHECK((CALL(a, getAvailableDimensionsForClassAttribute, w.vehicle, w.position) == DimensionHandleSet{w.x, w.y}));
    CHECK(a.rti->getAvailableDimensionsForClassAttribute(w.vehicle, w.speed).empty());
    CHECK((CALL(a, getAvailableDimensionsForInteractionClass, w.command) == DimensionHandleSet{w.x, w.y}));
    CHECK(CALL(a, normalizeFederateHandle, w.ha) != a.rti->normalizeFederateHandle(w.hb));
    CHECK(raises<InvalidFederateHandle>([&] { a.rti->normalizeFederateHandle(FederateHandle()); }));
    CHECK(CALL(a, normalizeServiceGroup, SUPPORT_SERVICES) == 6);
    CHECK(raises<InvalidServiceGroup>([&] { a.rti->normalizeServiceGroup(static_cast<ServiceGroup>(42)); }));
    CHECK(CALL(a, getAutomaticResignDirective) == CANCEL_THEN_DELETE_THEN_DIVEST);
    CALL(a, setAutomaticResignDirective, CANCEL_THEN_DELETE_THEN_DIVEST);
    CHECK(not_served([&] { a.rti->setAutomaticResignDirective(NO_ACTION); }));
    CHECK(raises<InvalidResignAction>([&] { a.rti->setAutomaticResignDirective(static_cast<ResignAction>(42)); }));
    CHECK(a.rti->getAutomaticResignDirective() == CANCEL_THEN_DELETE_THEN_DIVEST);
    CHECK(CALL(a, getUpdateRateValue, L"HLAfast") == 50.0);
    CHECK(raises<InvalidUpdateRateDesignator>([&] { a.rti->getUpdateRateValue(L"HLAwarp"); }));
    CHECK(raises<ObjectInstanceNotKnown>([&] { CALL(a, getUpdateRateValueForAttribute, ObjectInstanceHandle(), w.speed); }));
    CHECK(CALL(a, getFederateHandle, L"b") == w.hb && CALL(a, getFederateName, w.hb) == L"b");
    CHECK(raises<NameNotFound>([&] { a.rti->getFederateHandle(L"nobody"); }));
    const FederateHandle absent = a.rti->decodeFederateHandle(VariableLengthData("\0\0\0\x63", 4));
    CHECK(raises<FederateHandleNotKnown>([&] { a.rti->getFederateName(absent); }));
    auto factory = CALL(a, getTimeFactory);
    CHECK(factory->getName() == L"HLAfloat64Time" && factory->makeInitial()->toString() == at(0).toString());
}

// ---- declarations (§5) and the advisory switches that report on them (§10.32-10.39) ----
void declarations(World& w) {
    Federate& a = w.a;
    Federate& b = w.b;
    // Off, the class and interaction relevance switches keep quiet; on, they report b's subscriptions.
    CALL(a, disableObjectClassRelevanceAdvisorySwitch);
    CALL(a, disableInteractionRelevanceAdvisorySwitch);
    CALL(a, enableAttributeRelevanceAdvisorySwitch);
    CALL(a, publishObjectClassAttributes, w.vehicle, AttributeHandleSet{w.position, w.speed});
    CALL(a, publishInteractionClass, w.command);
    CALL(b, subscribeObjectClassAttributes, w.vehicle, AttributeHandleSet{w.position, w.speed});
    CALL(b, subscribeInteractionClass, w.command);
    settle({&b, &a});
    CHECK(a.rec.count("startRegistrationForObjectClass") == 0 && a.rec.count("turnInteractionsOn") == 0);
    CALL(a, enableObjectClassRelevanceAdvisorySwitch);
    CALL(a, enableInteractionRelevanceAdvisorySwitch);
    await(a, "startRegistrationForObjectClass", text(w.vehicle));
    await(a, "turnInteractionsOn", text(w.command));
    // An unpublished class cannot be registered; unpublishing its last attribute unpublishes it.
    a.rti->publishObjectClassAttributes(w.car, {w.doors});
    CALL(a, unpublishObjectClassAttributes, w.car, {w.doors});
    CHECK(raises<ObjectClassNotPublished>([&] { a.rti->registerObjectInstance(w.car); }));
}

// ---- objects (§6) ----
void objects(World& w) {
    Federate& a = w.a;
    Federate& b = w.b;
    const std::wstring fast = text(w.speed) + L"=fast";
    CALL(a, reserveObjectInstanceName, L"car-1");
    await(a, "objectInstanceNameReservationSucceeded", L"car-1");
    b.rti->reserveObjectInstanceName(L"car-1");
    await(b, "objectInstanceNameReservationFailed", L"car-1");
    CHECK(raises<ObjectInstanceNameNotReserved>([&] { a.rti->registerObjectInstance(w.vehicle, L"car-2"); }));
    w.v1 = CALL(a, registerObjectInstance, w.vehicle, L"car-1");
    w.v2 = CALL(a, registerObjectInstance, w.vehicle);
    w.v3 = a.rti->registerObjectInstance(w.vehicle);
    w.v4 = a.rti->registerObjectInstance(w.vehicle);
    CHECK(CALL(a, getObjectInstanceName, w.v1) == L"car-1" && CALL(a, getObjectInstanceHandle, L"car-1") == w.v1);
    await(b, "discoverObjectInstance", text(w.v1, w.vehicle, L"car-1"));
    until({&b}, [&] { return b.rec.count("discoverObjectInstance") == 4; }, "four objects discovered");
    CHECK(CALL(b, getKnownObjectClassHandle, w.v2) == w.vehicle);
    CHECK(b.rti->getUpdateRateValueForAttribute(w.v2, w.speed) == 0.0);  // subscribed with no rate
    // b subscribes to both attributes: a, with the attribute relevance switch on, is told to update them.
    await(a, "turnUpdatesOnForObjectInstance", text(w.v1, AttributeHandleSet{w.position, w.speed}));

    // One name, and several, reserved then released: free for b.
    a.rti->reserveObjectInstanceName(L"spare");
    settle({&a});
    CHECK(a.rec.has("objectInstanceNameReservationSucceeded", L"spare"));
    CALL(a, releaseObjectInstanceName, L"spare");
    settle({&a});  // the gateway has the release before b asks
    CHECK(raises<ObjectInstanceNameNotReserved>([&] { a.rti->registerObjectInstance(w.vehicle, L"spare"); }));
    b.rti->reserveObjectInstanceName(L"spare");
    await(b, "objectInstanceNameReservationSucceeded", L"spare");
    // A name in any script goes to the gateway and back as UTF-8; one that is not Unicode is refused.
    const std::wstring car = L"w\u00e4gen-\u20ac\U0001F697";
    b.rti->reserveObjectInstanceName(car);
    await(b, "objectInstanceNameReservationSucceeded", car);
    CHECK(raises<RTIinternalError>([&] { b.rti->reserveObjectInstanceName(std::wstring(1, static_cast<wchar_t>(0xD800))); },
                                   L"not Unicode"));
    const std::set<std::wstring> several{L"m1", L"m2"};
    CALL(a, reserveMultipleObjectInstanceName, several);
    await(a, "multipleObjectInstanceNameReservationSucceeded", text(several));
    b.rti->reserveMultipleObjectInstanceName(several);
    await(b, "multipleObjectInstanceNameReservationFailed", text(several));
    CALL(a, releaseMultipleObjectInstanceName, several);
    settle({&a});
    b.rti->reserveMultipleObjectInstanceName(several);
    await(b, "multipleObjectInstanceNameReservationSucceeded", text(several));
    CHECK(raises<NameSetWasEmpty>([&] { a.rti->reserveMultipleObjectInstanceName({}); }));

    // Values and interactions in receive order, with the tag; an attribute b stopped subscribing is not sent.
    CALL(a, updateAttributeValues, w.v1, AttributeHandleValueMap{{w.speed, data("fast")}}, data("t1"));
    await(b, "reflectAttributeValues", text(w.v1, L"{" + fast + L"}", L"t1", RECEIVE, RELIABLE) + L"|" + from(w));
    CALL(a, sendInteraction, w.command, ParameterHandleValueMap{{w.verb, data("go")}}, data("t2"));
    await(b, "receiveInteraction", text(w.command, L"{" + text(w.verb) + L"=go}", L"t2", RECEIVE, RELIABLE) + L"|" + from(w));
    CALL(b, unsubscribeObjectClassAttributes, w.vehicle, {w.speed});
    settle({&b});  // the gateway has it before a's update
    a.rti->updateAttributeValues(w.v1, {{w.speed, data("hidden")}, {w.position, data("shown")}}, data(""));
    await(b, "reflectAttributeValues", text(w.v1, L"{" + text(w.position) + L"=shown}", L"", RECEIVE, RELIABLE) + L"|" + from(w));
    b.rti->subscribeObjectClassAttributes(w.vehicle, {w.speed});

    // Update requests, of an object and of a class, reach the owner.
    CALL(b, requestAttributeValueUpdate, w.v1, AttributeHandleSet{w.speed}, data("ignored"));
    await(a, "provideAttributeValueUpdate", text(w.v1, AttributeHandleSet{w.speed}, L""));
    CALL(b, requestAttributeValueUpdate, w.vehicle, AttributeHandleSet{w.position}, data(""));
    await(a, "provideAttributeValueUpdate", text(w.v2, AttributeHandleSet{w.position}, L""));

    // Transportation: confirmed by callback, the next update sent best effort; reported to another federate
    // asking, as changed, else the FOM's.
    CALL(a, requestAttributeTransportationTypeChange, w.v1, AttributeHandleSet{w.speed}, BEST_EFFORT);
    await(a, "confirmAttributeTransportationTypeChange", text(w.v1, AttributeHandleSet{w.speed}, BEST_EFFORT));
    a.rti->updateAttributeValues(w.v1, {{w.speed, data("fast")}}, data("t3"));
    await(b, "reflectAttributeValues", text(w.v1, L"{" + fast + L"}", L"t3", RECEIVE, BEST_EFFORT) + L"|" + from(w));
    CALL(b, queryAttributeTransportationType, w.v1, w.speed);
    await(b, "reportAttributeTransportationType", text(w.v1, w.speed, BEST_EFFORT));
    b.rti->queryAttributeTransportationType(w.v1, w.position);
    await(b, "reportAttributeTransportationType", text(w.v1, w.position, RELIABLE));
    a.rti->requestInteractionTransportationTypeChange(w.command, BEST_EFFORT);
    settle({&a});  // the gateway has the change before b asks
    CALL(b, queryInteractionTransportationType, w.ha, w.command);
    await(b, "reportInteractionTransportationType", text(w.ha, w.command, BEST_EFFORT));
    CALL(a, requestInteractionTransportationTypeChange, w.command, RELIABLE);
    await(a, "confirmInteractionTransportationTypeChange", text(w.command, RELIABLE));
    settle({&a});
    b.rti->queryInteractionTransportationType(w.ha, w.command);
    await(b, "reportInteractionTransportationType", text(w.ha, w.command, RELIABLE));
    CHECK(b.rec.count("reportInteractionTransportationType") == 2);
    CHECK(raises<InvalidTransportationType>(
        [&] { a.rti->requestInteractionTransportationTypeChange(w.command, static_cast<TransportationType>(7)); }));
    CHECK(raises<ObjectInstanceNotKnown>([&] { b.rti->queryAttributeTransportationType(ObjectInstanceHandle(), w.speed); }));

    // Deleting: everywhere with a tag, or here only.
    CALL(a, deleteObjectInstance, w.v2, data("bye"));
    await(b, "removeObjectInstance", text(w.v2, L"bye", RECEIVE) + L"|" + from(w));
    CALL(b, localDeleteObjectInstance, w.v3);
    CHECK(raises<ObjectInstanceNotKnown>([&] { b.rti->getObjectInstanceName(w.v3); }));
    CHECK(a.rti->getObjectInstanceName(w.v3).size() > 0);
}

// ---- time management (§8), a regulating with lookahead 2, b constrained ----
void time_management(World& w) {
    Federate& a = w.a;
    Federate& b = w.b;
    const auto tso = [&](double t, MessageRetractionHandle h) { return text(at(t), TIMESTAMP, h, from(w)); };
    const auto value = [](auto h, const char* v) { return L"{" + text(h) + L"=" + wide(v) + L"}"; };
    CALL(a, enableTimeRegulation, HLAfloat64Interval(1.0));
    await(a, "timeRegulationEnabled", at(0).toString());
    CHECK(raises<TimeRegulationAlreadyEnabled>([&] { a.rti->enableTimeRegulation(HLAfloat64Interval(1.0)); }));
    CALL(b, enableTimeConstrained);
    await(b, "timeConstrainedEnabled", at(0).toString());
    CALL(a, modifyLookahead, HLAfloat64Interval(2.0));
    HLAfloat64Interval lookahead;
    CALL(a, queryLookahead, lookahead);
    CHECK(lookahead.getInterval() == 2.0);
    CHECK(raises<InvalidLookahead>([&] { a.rti->modifyLookahead(HLAinteger64Interval(1)); }));

    // a sends at 3, 4, 5 (speed now in timestamp order), 8 (retracted), and a command in receive order.
    const auto h3 = CALL(a, updateAttributeValues, w.v1, AttributeHandleValueMap{{w.position, data("p3")}}, data(""), at(3));
    const auto h4 = CALL(a, sendInteraction, w.command, ParameterHandleValueMap{{w.verb, data("c4")}}, data(""), at(4));
    CALL(a, changeAttributeOrderType, w.v1, AttributeHandleSet{w.speed}, TIMESTAMP);
    const auto h5 = a.rti->updateAttributeValues(w.v1, {{w.speed, data("s5")}}, data(""), at(5));
    const auto h8 = a.rti->updateAttributeValues(w.v1, {{w.position, data("p8")}}, data(""), at(8));
    CALL(a, retract, h8);
    CHECK(raises<InvalidMessageRetractionHandle>([&] { a.rti->retract(MessageRetractionHandle()); }));
    CHECK(raises<InvalidLogicalTime>([&] { a.rti->timeAdvanceRequest(HLAinteger64Time(1)); }));
    CALL(a, changeInteractionOrderType, w.command, RECEIVE);
    a.rti->sendInteraction(w.command, {{w.verb, data("ro")}}, data(""), at(5));
    CALL(a, timeAdvanceRequest, at(6));  // a is not constrained: granted at once
    await(a, "timeAdvanceGrant", at(6).toString());
    // Receive-order messages reach a constrained federate between advances only with asynchronous delivery.
    CALL(b, enableAsynchronousDelivery);
    CHECK(raises<AsynchronousDeliveryAlreadyEnabled>([&] { b.rti->enableAsynchronousDelivery(); }));
    await(b, "receiveInteraction", text(w.command, value(w.verb, "ro"), L"", RECEIVE, RELIABLE, from(w)));
    CALL(b, disableAsynchronousDelivery);
    CHECK(raises<AsynchronousDeliveryAlreadyDisabled>([&] { b.rti->disableAsynchronousDelivery(); }));

    // b's advances, each granted after the messages up to its time (a at 6 + lookahead 2 bounds b at 8).
    CALL(b, timeAdvanceRequest, at(3));
    await(b, "timeAdvanceGrant", at(3).toString());
    CHECK(b.rec.has("reflectAttributeValues", text(w.v1, value(w.position, "p3"), L"", TIMESTAMP, RELIABLE) + L"|" + tso(3, h3)));
    CALL(b, nextMessageRequest, at(7));  // the next message, at 4
    await(b, "timeAdvanceGrant", at(4).toString());
    CHECK(b.rec.has("receiveInteraction", text(w.command, value(w.verb, "c4"), L"", TIMESTAMP, RELIABLE) + L"|" + tso(4, h4)));
    CALL(b, timeAdvanceRequestAvailable, at(5));
    await(b, "timeAdvanceGrant", at(5).toString());
    CHECK(b.rec.has("reflectAttributeValues", text(w.v1, value(w.speed, "s5"), L"", TIMESTAMP, BEST_EFFORT) + L"|" + tso(5, h5)));
    CALL(b, nextMessageRequestAvailable, at(7));  // none before 7: p8 was retracted
    await(b, "timeAdvanceGrant", at(7).toString());
    HLAfloat64Time t;
    CHECK(CALL(b, queryGALT, t) && t.getTime() == 8);
    CALL(b, queryLogicalTime, t);
    CHECK(t.getTime() == 7);
    CHECK(CALL(b, queryLITS, t) && t.getTime() == 8);
    CHECK(raises<InvalidLogicalTime>([&] {
        HLAinteger64Time wrong;
        b.rti->queryLogicalTime(wrong);
    }));

    // Flushing delivers what is queued (a's update at 9) at once; a's retraction then reaches b as a request.
    const auto h9 = a.rti->updateAttributeValues(w.v1, {{w.position, data("p9")}}, data(""), at(9));
    settle({&a});  // queued for b before b flushes
    CALL(b, flushQueueRequest, at(20));
    until({&b}, [&] { return b.rec.count("timeAdvanceGrant") == 5; }, "the flush's grant");
    CHECK(b.rec.has("reflectAttributeValues", text(w.v1, value(w.position, "p9"), L"", TIMESTAMP, RELIABLE) + L"|" + tso(9, h9)));
    a.rti->retract(h9);
    await(b, "requestRetraction", h9.toString());
    CHECK(!b.rec.seen("reflectAttributeValues", L"=p8}"));

    // A timestamped deletion.
    const auto h10 = CALL(a, deleteObjectInstance, w.v4, data("late"), at(10));
    a.rti->timeAdvanceRequest(at(9));
    b.rti->timeAdvanceRequest(at(10));
    await(b, "timeAdvanceGrant", at(10).toString());
    CHECK(b.rec.has("removeObjectInstance", text(w.v4, L"late", TIMESTAMP, at(10), TIMESTAMP, h10, from(w))));
    CHECK(CALL(a, decodeMessageRetractionHandle, h10.encode()) == h10);

    CALL(a, disableTimeRegulation);
    CHECK(raises<TimeRegulationIsNotEnabled>([&] { a.rti->disableTimeRegulation(); }));
    CALL(b, disableTimeConstrained);
    CHECK(raises<TimeConstrainedIsNotEnabled>([&] { b.rti->disableTimeConstrained(); }));
}

// ---- ownership (§7) between a and b ----
void ownership(World& w) {
    Federate& a = w.a;
    Federate& b = w.b;
    const AttributeHandleSet speed{w.speed}, position{w.position};
    b.rti->publishObjectClassAttributes(w.vehicle, {w.position, w.speed});
    // b asks for speed: a denies, then gives what was wanted.
    CALL(b, attributeOwnershipAcquisition, w.v1, speed, data("want"));
    await(a, "requestAttributeOwnershipRelease", text(w.v1, speed, L"want"));
    CALL(a, attributeOwnershipReleaseDenied, w.v1, speed);
    CHECK(CALL(a, isAttributeOwnedByFederate, w.v1, w.speed));
    AttributeHandleSet divested;
    CALL(a, attributeOwnershipDivestitureIfWanted, w.v1, AttributeHandleSet{w.speed, w.position}, divested);
    CHECK(divested == speed);
    await(b, "attributeOwnershipAcquisitionNotification", text(w.v1, speed, L""));
    CHECK(b.rti->isAttributeOwnedByFederate(w.v1, w.speed) && !a.rti->isAttributeOwnedByFederate(w.v1, w.speed));
    // a offers position, withdraws, offers again; b takes it, a confirms.
    CALL(a, negotiatedAttributeOwnershipDivestiture, w.v1, position, data("offer"));
    await(b, "requestAttributeOwnershipAssumption", text(w.v1, position, L"offer"));
    CALL(a, cancelNegotiatedAttributeOwnershipDivestiture, w.v1, position);
    CHECK(raises<AttributeDivestitureWasNotRequested>([&] { a.rti->cancelNegotiatedAttributeOwnershipDivestiture(w.v1, position); }));
    CHECK(raises<AttributeDivestitureWasNotRequested>([&] { a.rti->confirmDivestiture(w.v1, position, data("")); }));
    a.rti->negotiatedAttributeOwnershipDivestiture(w.v1, position, data("again"));
    await(b, "requestAttributeOwnershipAssumption", text(w.v1, position, L"again"));
    b.rti->attributeOwnershipAcquisition(w.v1, position, data(""));
    await(a, "requestDivestitureConfirmation", text(w.v1, position));
    CALL(a, confirmDivestiture, w.v1, position, data(""));
    await(b, "attributeOwnershipAcquisitionNotification", text(w.v1, position, L""));
    CHECK(b.rti->isAttributeOwnedByFederate(w.v1, w.position) && !a.rti->isAttributeOwnedByFederate(w.v1, w.position));
    // b drops speed: nobody owns it until a takes it if available.
    CALL(b, unconditionalAttributeOwnershipDivestiture, w.v1, speed);
    CALL(b, queryAttributeOwnership, w.v1, w.speed);
    await(b, "attributeIsNotOwned", text(w.v1, w.speed));
    CALL(a, attributeOwnershipAcquisitionIfAvailable, w.v1, speed);
    await(a, "attributeOwnershipAcquisitionNotification", text(w.v1, speed, L""));
    a.rti->queryAttributeOwnership(w.v1, w.position);
    await(a, "informAttributeOwnership", text(w.v1, w.position, w.hb));
    // a asks for position back, then cancels.
    a.rti->attributeOwnershipAcquisition(w.v1, position, data("back"));
    await(b, "requestAttributeOwnershipRelease", text(w.v1, position, L"back"));
    CALL(a, cancelAttributeOwnershipAcquisition, w.v1, position);
    await(a, "confirmAttributeOwnershipAcquisitionCancellation", text(w.v1, position));
    CHECK(b.rti->isAttributeOwnedByFederate(w.v1, w.position));
}

// ---- regions (§9) over the modules' dimensions X [0, 1000) and Y [0, 500) ----
void regions(World& w) {
    Federate& a = w.a;
    Federate& b = w.b;
    const AttributeHandleSet position{w.position};
    const auto reflected = [&](const char* v) { return L"{" + text(w.position) + L"=" + wide(v) + L"}"; };
    // Without subscriptions of the default region (the whole space), b's regions decide what reaches it.
    CALL(b, unsubscribeObjectClass, w.vehicle);
    await(a, "stopRegistrationForObjectClass", text(w.vehicle));
    CALL(b, unsubscribeInteractionClass, w.command);
    await(a, "turnInteractionsOff", text(w.command));
    CALL(a, disableAttributeRelevanceAdvisorySwitch);  // no turnUpdatesOn for what follows
    CALL(b, enableAttributeScopeAdvisorySwitch);

    const RegionHandle wanted = CALL(b, createRegion, DimensionHandleSet{w.x});
    CHECK((CALL(b, getDimensionHandleSet, wanted) == DimensionHandleSet{w.x}));
    CHECK(bounds(CALL(b, getRangeBounds, wanted, w.x)) == std::make_pair(0ul, 1000ul));
    CALL(b, setRangeBounds, wanted, w.x, RangeBounds(0, 100));
    CHECK(bounds(b.rti->getRangeBounds(wanted, w.x)) == std::make_pair(0ul, 100ul));
    CHECK(raises<InvalidRangeBound>([&] { b.rti->setRangeBounds(wanted, w.x, RangeBounds(10, 1001)); }));
    CHECK(raises<RegionDoesNotContainSpecifiedDimension>([&] { b.rti->getRangeBounds(wanted, w.y); }));
    CHECK(raises<RegionNotCreatedByThisFederate>([&] { a.rti->getRangeBounds(wanted, w.x); }));
    CALL(b, commitRegionModifications, RegionHandleSet{wanted});
    CALL(b, subscribeObjectClassAttributesWithRegions, w.vehicle, in(position, {wanted}));
    CALL(b, subscribeInteractionClassWithRegions, w.command, RegionHandleSet{wanted});
    settle({&b});  // the gateway has b's subscriptions before a's updates

    const RegionHandle far = a.rti->createRegion({w.x, w.y});
    const RegionHandle near = a.rti->createRegion({w.x});
    a.rti->setRangeBounds(far, w.x, RangeBounds(500, 600));
    a.rti->setRangeBounds(near, w.x, RangeBounds(50, 60));
    a.rti->commitRegionModifications({far, near});
    a.rti->reserveObjectInstanceName(L"ddm-1");
    await(a, "objectInstanceNameReservationSucceeded", L"ddm-1");
    const auto d1 = CALL(a, registerObjectInstanceWithRegions, w.vehicle, in(position, {far}), L"ddm-1");
    const auto d2 = CALL(a, registerObjectInstanceWithRegions, w.vehicle, in(position, {near}));
    const auto update = [&](ObjectInstanceHandle o, const char* v) { a.rti->updateAttributeValues(o, {{w.position, data(v)}}, data("")); };
    const auto send = [&](RegionHandle r, const char* v) {
        CALL(a, sendInteractionWithRegions, w.command, ParameterHandleValueMap{{w.verb, data(v)}}, RegionHandleSet{r}, data(""));
    };
    update(d1, "far");
    update(d2, "near-2");
    send(far, "far");
    send(near, "near");
    const auto timed = CALL(a, sendInteractionWithRegions, w.command, ParameterHandleValueMap{{w.verb, data("timed")}},
                            RegionHandleSet{near}, data(""), at(50));
    CHECK(timed.isValid());
    CALL(a, associateRegionsForUpdates, d1, in(position, {near}));
    update(d1, "near-1");
    a.rti->setRangeBounds(near, w.x, RangeBounds(200, 300));
    a.rti->commitRegionModifications({near});
    update(d1, "moved");
    CALL(a, unassociateRegionsForUpdates, d1, in(position, {far, near}));  // associating near added it to far
    update(d1, "free");  // the default region: the whole space
    until({&b}, [&] { return b.rec.seen("reflectAttributeValues", reflected("free")) &&
                             b.rec.seen("receiveInteraction", text(w.verb) + L"=timed}"); },
          "the updates and interactions in regions");
    settle({&a, &b});
    // What b got in its region, in order: near-2, near-1, free (not far, not moved).
    std::vector<std::wstring> got;
    for (auto const& r : b.rec.all("reflectAttributeValues")) {
        for (const char* v : {"far", "near-2", "near-1", "moved", "free"})
            if (r.find(reflected(v)) != std::wstring::npos) got.push_back(wide(v));
    }
    CHECK((got == std::vector<std::wstring>{L"near-2", L"near-1", L"free"}));
    CHECK(b.rec.has("receiveInteraction", text(w.command, L"{" + text(w.verb) + L"=near}", L"", RECEIVE, RELIABLE, from(w))));
    CHECK(!b.rec.has("receiveInteraction", text(w.command, L"{" + text(w.verb) + L"=far}", L"", RECEIVE, RELIABLE, from(w))));
    CHECK(b.rec.has("attributesInScope", text(d2, position)) && b.rec.has("attributesOutOfScope", text(d2, position)));
    CHECK(!a.rec.has("turnUpdatesOnForObjectInstance", text(d2, position)));

    // Several regions: d1's position is updated in far and in `also`, which overlaps b's region, and reflected
    // once; an interaction sent in both is received once; unassociating (position, also) keeps far, outside.
    const RegionHandle also = a.rti->createRegion({w.x});
    a.rti->setRangeBounds(also, w.x, RangeBounds(10, 90));
    a.rti->commitRegionModifications({also});
    CALL(a, associateRegionsForUpdates, d1, in(position, {far, also}));
    update(d1, "twice");
    CALL(a, sendInteractionWithRegions, w.command, ParameterHandleValueMap{{w.verb, data("twice")}},
         RegionHandleSet{far, also}, data(""));
    CALL(a, unassociateRegionsForUpdates, d1, in(position, {also}));
    CHECK(raises<RegionInUseForUpdateOrSubscription>([&] { a.rti->deleteRegion(far); }));
    update(d1, "far only");
    settle({&a, &b});
    const auto times = [&](const char* name, std::wstring const& part) {
        size_t n = 0;
        for (auto const& r : b.rec.all(name)) n += r.find(part) != std::wstring::npos;
        return n;
    };
    CHECK(times("reflectAttributeValues", reflected("twice")) == 1);
    CHECK(times("receiveInteraction", text(w.verb) + L"=twice}") == 1);
    CHECK(times("reflectAttributeValues", reflected("far only")) == 0);
    CALL(a, unassociateRegionsForUpdates, d1, in(position, {far}));
    a.rti->deleteRegion(also);
    settle({&a, &b});  // d1's coming back into b's scope told before the switch goes off

    // Off, the scope switch keeps quiet when d2 comes back in b's region.
    CALL(b, disableAttributeScopeAdvisorySwitch);
    const size_t in_scope = b.rec.count("attributesInScope");
    a.rti->setRangeBounds(near, w.x, RangeBounds(50, 60));
    a.rti->commitRegionModifications({near});
    settle({&a});  // the gateway has the commit before b's request
    CALL(b, requestAttributeValueUpdateWithRegions, w.vehicle, in(position, {wanted}), data(""));
    await(a, "provideAttributeValueUpdate", text(d2, position, L""));
    settle({&a, &b});
    CHECK(b.rec.count("attributesInScope") == in_scope);

    // Unsubscribed, b gets nothing more; regions in use cannot be deleted, others can, once.
    CALL(b, unsubscribeObjectClassAttributesWithRegions, w.vehicle, in(position, {wanted}));
    CALL(b, unsubscribeInteractionClassWithRegions, w.command, RegionHandleSet{wanted});
    const size_t reflections = b.rec.count("reflectAttributeValues"), interactions = b.rec.count("receiveInteraction");
    update(d2, "after");
    a.rti->sendInteractionWithRegions(w.command, {{w.verb, data("after")}}, {near}, data(""));
    settle({&a, &b});
    CHECK(b.rec.count("reflectAttributeValues") == reflections && b.rec.count("receiveInteraction") == interactions);
    CHECK(raises<RegionInUseForUpdateOrSubscription>([&] { a.rti->deleteRegion(near); }));
    CALL(b, deleteRegion, wanted);
    CHECK(raises<RegionNotCreatedByThisFederate>([&] { b.rti->deleteRegion(wanted); }));
    CHECK(CALL(a, decodeRegionHandle, far.encode()) == far);
    CHECK(CALL(a, decodeDimensionHandle, w.x.encode()) == w.x);
}

// ---- synchronization points, save and restore (§4.11-4.21) ----
void sync_save_restore(World& w) {
    Federate& a = w.a;
    Federate& b = w.b;
    const auto both = [&](std::string const& name, std::wstring const& args) {
        for (Federate* f : {&a, &b}) await(*f, name, args);
    };
    CALL(a, registerFederationSynchronizationPoint, L"all", data("x"));
    await(a, "synchronizationPointRegistrationSucceeded", L"all");
    both("announceSynchronizationPoint", L"all|x");
    CALL(a, synchronizationPointAchieved, L"all");
    b.rti->synchronizationPointAchieved(L"all");
    both("federationSynchronized", L"all|{}");
    CALL(a, registerFederationSynchronizationPoint, L"just-b", data("y"), FederateHandleSet{w.hb});
    await(b, "announceSynchronizationPoint", L"just-b|y");
    b.rti->synchronizationPointAchieved(L"just-b");
    await(b, "federationSynchronized", L"just-b|{}");
    settle({&a});
    CHECK(!a.rec.has("announceSynchronizationPoint", L"just-b|y"));
    a.rti->registerFederationSynchronizationPoint(L"all", data(""));
    a.rti->registerFederationSynchronizationPoint(L"all", data(""));
    await(a, "synchronizationPointRegistrationFailed", text(L"all", SYNCHRONIZATION_POINT_LABEL_NOT_UNIQUE));
    CHECK(not_served([&] { a.rti->synchronizationPointAchieved(L"all", false); }));
    CHECK(raises<SynchronizationPointLabelNotAnnounced>([&] { a.rti->synchronizationPointAchieved(L"never"); }));

    // A save both complete, and a timed one (nobody is time-managed: at once) that b cannot.
    CALL(a, requestFederationSave, L"s1");
    both("initiateFederateSave", L"s1");
    for (Federate* f : {&a, &b}) {
        CALL(*f, federateSaveBegun);
        CALL(*f, federateSaveComplete);
    }
    both("federationSaved", L"");
    CHECK(raises<SaveNotInProgress>([&] { CALL(a, abortFederationSave); }));
    CALL(a, requestFederationSave, L"s2", at(50));
    both("initiateFederateSave", L"s2");
    a.rti->federateSaveBegun();
    a.rti->federateSaveComplete();
    CALL(a, queryFederationSaveStatus);  // a has saved, b is told to
    await(a, "federationSaveStatusResponse", w.ha.toString() + L"=" + std::to_wstring(FEDERATE_WAITING_FOR_FEDERATION_TO_SAVE) +
                                                 L";" + w.hb.toString() + L"=" + std::to_wstring(FEDERATE_INSTRUCTED_TO_SAVE) + L";");
    b.rti->federateSaveBegun();
    CALL(b, federateSaveNotComplete);
    both("federationNotSaved", text(FEDERATE_REPORTED_FAILURE_DURING_SAVE));
    // A save aborted by b while a has answered: both hear it was aborted.
    a.rti->requestFederationSave(L"s3");
    both("initiateFederateSave", L"s3");
    a.rti->federateSaveBegun();
    a.rti->federateSaveComplete();
    b.rti->abortFederationSave();
    both("federationNotSaved", text(SAVE_ABORTED));

    // Restores: of an unknown label, refused; of s1, both complete; again, b cannot.
    CALL(a, requestFederationRestore, L"nothing");
    await(a, "requestFederationRestoreFailed", L"nothing");
    a.rti->requestFederationRestore(L"s1");
    await(a, "requestFederationRestoreSucceeded", L"s1");
    both("federationRestoreBegun", L"");
    await(a, "initiateFederateRestore", text(L"s1", L"a", w.ha));
    await(b, "initiateFederateRestore", text(L"s1", L"b", w.hb));
    CALL(a, federateRestoreComplete);
    b.rti->federateRestoreComplete();
    both("federationRestored", L"");
    CHECK(raises<RestoreNotInProgress>([&] { CALL(a, abortFederationRestore); }));
    a.rti->requestFederationRestore(L"s1");
    until({&a, &b}, [&] { return a.rec.count("initiateFederateRestore") == 2 && b.rec.count("initiateFederateRestore") == 2; },
          "the second restore");
    a.rti->federateRestoreComplete();
    CALL(a, queryFederationRestoreStatus);  // a has restored, b is restoring
    const std::wstring ha = w.ha.toString(), hb = w.hb.toString();
    await(a, "federationRestoreStatusResponse",
          ha + L">" + ha + L"=" + std::to_wstring(FEDERATE_WAITING_FOR_FEDERATION_TO_RESTORE) + L";" + hb + L">" + hb +
              L"=" + std::to_wstring(FEDERATE_RESTORING) + L";");
    CALL(b, federateRestoreNotComplete);
    both("federationNotRestored", text(FEDERATE_REPORTED_FAILURE_DURING_RESTORE));
    // A restore aborted by b while a has answered.
    a.rti->requestFederationRestore(L"s1");
    until({&a, &b}, [&] { return a.rec.count("initiateFederateRestore") == 3 && b.rec.count("initiateFederateRestore") == 3; },
          "the third restore");
    a.rti->federateRestoreComplete();
    b.rti->abortFederationRestore();
    both("federationNotRestored", text(RESTORE_ABORTED));
}

// ---- the callback services on one event (§10.41-10.44), the handles' decoding (§10.45) ----
void callbacks_and_decoding(World& w) {
    Federate& a = w.a;
    // One callback pending (the reservation's answer, queued before the round trip's): evokeCallback gives it.
    settle({&a});
    a.rti->reserveObjectInstanceName(L"one-callback");
    CHECK(raises<FederationExecutionDoesNotExist>([&] { a.rti->destroyFederationExecution(L"no-such"); }));
    const size_t before = a.rec.size();
    CHECK(!CALL(a, evokeCallback, 1.0) && a.rec.size() == before + 1);
    CHECK(a.rec.has("objectInstanceNameReservationSucceeded", L"one-callback"));
    // Disabled, callbacks wait (evoking says one is pending) until enabled again.
    CALL(a, disableCallbacks);
    a.rti->reserveObjectInstanceName(L"held");
    CHECK(raises<FederationExecutionDoesNotExist>([&] { a.rti->destroyFederationExecution(L"no-such"); }));
    CHECK(a.rti->evokeMultipleCallbacks(0.0, 0.1) && !a.rec.has("objectInstanceNameReservationSucceeded", L"held"));
    CALL(a, enableCallbacks);
    await(a, "objectInstanceNameReservationSucceeded", L"held");

    CHECK(CALL(a, decodeFederateHandle, w.hb.encode()) == w.hb);
    CHECK(CALL(a, decodeObjectClassHandle, w.car.encode()) == w.car);
    CHECK(CALL(a, decodeInteractionClassHandle, w.command.encode()) == w.command);
    CHECK(CALL(a, decodeObjectInstanceHandle, w.v1.encode()) == w.v1);
    CHECK(CALL(a, decodeAttributeHandle, w.doors.encode()) == w.doors);
    CHECK(CALL(a, decodeParameterHandle, w.verb.encode()) == w.verb);
    CHECK(raises<CouldNotDecode>([&] { a.rti->decodeAttributeHandle(data("abc")); }));
    CHECK(raises<CouldNotDecode>([&] { a.rti->decodeMessageRetractionHandle(data("abcd")); }));
}

// ---- a FOM module added at join (§4.9): d joins with the Cars module; c, joined before, learns the extended
// FOM as it arrives (its thread reads it), every handle it knew unchanged ----
void module_added_at_join(World& w, std::wstring const& cars) {
    Federate& c = w.c;
    const ObjectClassHandle vehicle = c.rti->getObjectClassHandle(L"Vehicle");
    const AttributeHandle position = c.rti->getAttributeHandle(vehicle, L"position");
    CHECK(raises<NameNotFound>([&] { c.rti->getObjectClassHandle(L"Vehicle.Car"); }));
    Federate d{"d"};
    d.rti->connect(d.rec, HLA_EVOKED, w.address);
    CHECK(raises<CouldNotOpenFDD>([&] { d.rti->joinFederationExecution(L"d", L"test", L"Integers", {L"missing.xml"}); }));
    d.rti->joinFederationExecution(L"d", L"test", L"Integers", {cars});
    const ObjectClassHandle car = d.rti->getObjectClassHandle(L"Vehicle.Car");
    const AttributeHandle doors = d.rti->getAttributeHandle(car, L"doors");
    ObjectClassHandle learned;
    until({&c}, [&] {
        try {
            learned = c.rti->getObjectClassHandle(L"Vehicle.Car");
            return true;
        } catch (NameNotFound const&) {
            return false;
        }
    }, "the extended FOM");
    CHECK(learned == car && c.rti->getObjectClassHandle(L"Vehicle") == vehicle);
    CHECK(c.rti->getAttributeHandle(car, L"position") == position && c.rti->getAttributeHandle(car, L"doors") == doors);
    d.rti->resignFederationExecution(NO_ACTION);
    d.rti->disconnect();
}

// ---- an HLA_IMMEDIATE federate in an HLAinteger64Time federation ----
void immediate_integer_time(World& w, std::wstring const& vehicles, std::wstring const& cars) {
    Federate& c = w.c;
    c.evoked = false;
    CALL(c, connect, c.rec, HLA_IMMEDIATE, w.address);
    CHECK(raises<FederateNameAlreadyInUse>([&] { c.rti->joinFederationExecution(L"a", L"test", L"Services"); }));
    c.rti->createFederationExecution(L"Integers", vehicles, L"HLAinteger64Time");
    const FederateHandle hc = CALL(c, joinFederationExecution, L"test", L"Integers");
    CHECK(hc.isValid() && c.rti->getTimeFactory()->getName() == L"HLAinteger64Time");
    module_added_at_join(w, cars);
    c.rti->enableTimeRegulation(HLAinteger64Interval(2));
    await(c, "timeRegulationEnabled", HLAinteger64Time(0).toString());  // nobody evokes
    HLAinteger64Interval lookahead;
    c.rti->queryLookahead(lookahead);
    CHECK(lookahead.getInterval() == 2);
    CHECK(raises<InvalidLogicalTime>([&] { c.rti->timeAdvanceRequest(at(1)); }));
    c.rti->disableCallbacks();  // held back until enabled again
    c.rti->timeAdvanceRequest(HLAinteger64Time(3));
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    CHECK(c.rec.count("timeAdvanceGrant") == 0);
    c.rti->enableCallbacks();
    await(c, "timeAdvanceGrant", HLAinteger64Time(3).toString());
    HLAinteger64Time now;
    c.rti->queryLogicalTime(now);
    CHECK(now.getTime() == 3);
    CHECK(!c.rti->evokeCallback(0.0));  // the ambassador's thread delivers, not the caller
    c.rti->resignFederationExecution(NO_ACTION);
    c.rti->destroyFederationExecution(L"Integers");
    c.rti->disconnect();
}

// ---- the end: unpublishing, resigning, destroying, disconnecting ----
void finish(World& w) {
    Federate& a = w.a;
    Federate& b = w.b;
    CALL(a, unpublishInteractionClass, w.command);
    CHECK(raises<InteractionClassNotPublished>([&] { a.rti->sendInteraction(w.command, {}, data("")); }));
    CALL(a, unpublishObjectClass, w.vehicle);
    CHECK(raises<ObjectClassNotPublished>([&] { a.rti->registerObjectInstance(w.vehicle); }));
    CHECK(raises<FederateIsExecutionMember>([&] { CALL(a, disconnect); }));
    CHECK(raises<InvalidResignAction>([&] { a.rti->resignFederationExecution(static_cast<ResignAction>(42)); }));
    CALL(b, resignFederationExecution, CANCEL_THEN_DELETE_THEN_DIVEST);
    CHECK(raises<FederateNotExecutionMember>([&] { b.rti->getObjectClassHandle(L"Vehicle"); }));
    CHECK(raises<FederatesCurrentlyJoined>([&] { a.rti->destroyFederationExecution(L"Services"); }));
    a.rti->resignFederationExecution(DELETE_OBJECTS_THEN_DIVEST);
    a.rti->destroyFederationExecution(L"Services");
    CHECK(raises<FederationExecutionDoesNotExist>([&] { a.rti->destroyFederationExecution(L"Services"); }));
    a.rti->disconnect();
    b.rti->disconnect();
    CHECK(raises<NotConnected>([&] { a.rti->getObjectClassHandle(L"Vehicle"); }));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3 && argc != 4)
        return std::fprintf(stderr, "usage: rti1516e_services VEHICLES_XML CARS_XML [ADDRESS]\n"), 2;
    const std::wstring vehicles = wide(argv[1]), cars = wide(argv[2]);
    World w;
    w.address = argc == 4 ? wide(argv[3]) : L"";  // empty: $HLACORE_RTIG
    everyone = {&w.a, &w.b, &w.c};
    std::atexit(show_events);
    try {
        connect_create_join(w, vehicles, cars);
        support(w);
        declarations(w);
        objects(w);
        time_management(w);
        ownership(w);
        regions(w);
        sync_save_restore(w);
        callbacks_and_decoding(w);
        immediate_integer_time(w, vehicles, cars);
        finish(w);
    } catch (Exception const& e) {
        std::wcerr << L"unexpected " << e.what() << std::endl;
        show_events();
        everyone.clear();  // w goes before the exit handlers run
        return 1;
    }
    everyone.clear();
    for (int i = 0; i < kEntries; ++i)
        if (!called.count(i)) std::fprintf(stderr, "not called: entry %d, %s\n", i, kNames[i]);
    std::printf("called %zu services\n", called.size());
    return called.size() == static_cast<size_t>(kEntries) ? 0 : 1;
}
