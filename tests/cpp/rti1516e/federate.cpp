// A C++ federate of the IEEE 1516-2010 API (tests/rti/test_rti1516e_cpp.py runs it with Python federates):
// connects to ADDRESS, joins the Vehicles federation (tests/data/rti1516e) as NAME, checks services whose
// answers it knows (lookups, the standard's exceptions, handle encodings, times), registers a vehicle under a
// reserved name, then, from synchronization point "go", runs STEPS steps of a TSO lockstep with PEERS other
// federates (regulating and constrained, lookahead 1: its position at t, then timeAdvanceRequest(t)).
// Prints {"ready": ...} once set up and, at the end, one JSON line: the steps, the timestamped reflections,
// and the grants that came before every peer's update at their time ("late").
#include <RTI/RTI1516.h>
#include <RTI/time/HLAfloat64Interval.h>
#include <RTI/time/HLAfloat64Time.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <string>

#include "../check.hh"

using namespace rti1516e;


namespace {

std::wstring wide(std::string const& s) { return std::wstring(s.begin(), s.end()); }

// Records what the lockstep needs: the grants, and the timestamped reflections by time.
struct Federate : NullFederateAmbassador {
    std::map<std::string, int> counts;
    std::map<double, int> reflected_at;  // timestamped reflections by their time
    double granted = -1;
    int late = 0;
    int peers = 0;
    int reflections = 0;
    std::wstring reserved;
    std::map<std::wstring, std::wstring> listed;  // reportFederationExecutions: name -> time type

    void announceSynchronizationPoint(std::wstring const&, VariableLengthData const&) override { ++counts["announce"]; }
    void federationSynchronized(std::wstring const&, FederateHandleSet const&) override { ++counts["synchronized"]; }
    void objectInstanceNameReservationSucceeded(std::wstring const& name) override { reserved = name; }
    void reportFederationExecutions(FederationExecutionInformationVector const& federations) override {
        for (const auto& f : federations) listed[f.federationExecutionName] = f.logicalTimeImplementationName;
    }
    void discoverObjectInstance(ObjectInstanceHandle, ObjectClassHandle, std::wstring const&) override {
        ++counts["discover"];
    }
    void reflectAttributeValues(ObjectInstanceHandle, AttributeHandleValueMap const& values, VariableLengthData const&,
                                OrderType sent, TransportationType, LogicalTime const& time, OrderType received,
                                MessageRetractionHandle handle, SupplementalReflectInfo info) override {
        CHECK(sent == TIMESTAMP && received == TIMESTAMP && handle.isValid() && info.hasProducingFederate);
        CHECK(values.size() == 1 && values.begin()->second.size() > 0);
        ++reflections;
        ++reflected_at[dynamic_cast<HLAfloat64Time const&>(time).getTime()];
    }
    void timeRegulationEnabled(LogicalTime const&) override { ++counts["regulating"]; }
    void timeConstrainedEnabled(LogicalTime const&) override { ++counts["constrained"]; }
    void timeAdvanceGrant(LogicalTime const& time) override {
        granted = dynamic_cast<HLAfloat64Time const&>(time).getTime();
        if (reflected_at[granted] != peers) ++late;
    }
};

void until(RTIambassador& rti, std::function<bool()> done, const char* what) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!done()) {
        if (std::chrono::steady_clock::now() > deadline) {
            std::fprintf(stderr, "timed out waiting for %s\n", what);
            std::exit(1);
        }
        rti.evokeMultipleCallbacks(0.01, 0.1);
    }
}

// Runs `call`, which must raise E.
template <class E>
bool raises(std::function<void()> call) {
    try {
        call();
    } catch (E const&) {
        return true;
    }
    return false;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 5) return std::fprintf(stderr, "usage: rti1516e_federate ADDRESS NAME STEPS PEERS\n"), 2;
    const std::string name = argv[2];
    const int steps = std::stoi(argv[3]);
    Federate fed;
    fed.peers = std::stoi(argv[4]);
    try {
        RTIambassadorFactory factory;
        std::unique_ptr<RTIambassador> rti = factory.createRTIambassador();
        CHECK(raises<InvalidLocalSettingsDesignator>([&] { rti->connect(fed, HLA_EVOKED, L"no address"); }));
        rti->connect(fed, HLA_EVOKED, L"rti://" + wide(argv[1]) + L"/");
        CHECK(raises<AlreadyConnected>([&] { rti->connect(fed, HLA_EVOKED, wide(argv[1])); }));
        CHECK(rtiName() == L"hlacore" && rtiVersion().find(L"1516") != std::wstring::npos);
        rti->joinFederationExecution(wide(name), L"test", L"Vehicles");

        // Lookups, the standard's exceptions, encodings, times.
        const ObjectClassHandle vehicle = rti->getObjectClassHandle(L"Vehicle");
        const AttributeHandle position = rti->getAttributeHandle(vehicle, L"position");
        CHECK(rti->getObjectClassName(vehicle) == L"HLAobjectRoot.Vehicle" || rti->getObjectClassName(vehicle) == L"Vehicle");
        CHECK(rti->getAttributeName(vehicle, position) == L"position");
        CHECK(raises<NameNotFound>([&] { rti->getObjectClassHandle(L"Spaceship"); }));
        CHECK(raises<NameNotFound>([&] { rti->getAttributeHandle(vehicle, L"altitude"); }));
        CHECK(rti->decodeAttributeHandle(position.encode()) == position);
        CHECK(raises<CouldNotDecode>([&] { rti->decodeObjectClassHandle(VariableLengthData("ab", 2)); }));
        CHECK(!AttributeHandle().isValid() && position.isValid());
        const SupplementalReceiveInfo from_handle = rti->getFederateHandle(wide(name));  // implicit, as standard
        const NameNotFound from_text = std::wstring(L"why");
        CHECK(from_handle.hasProducingFederate && from_text.what() == L"why");
        CHECK(rti->getTimeFactory()->getName() == L"HLAfloat64Time");
        CHECK(rti->getOrderType(L"TimeStamp") == TIMESTAMP && rti->getTransportationName(RELIABLE) == L"HLAreliable");
        const DimensionHandleSet dims = rti->getAvailableDimensionsForClassAttribute(vehicle, position);
        CHECK(dims.size() == 2 && rti->getDimensionUpperBound(rti->getDimensionHandle(L"X")) == 1000);
        CHECK(rti->getFederateName(rti->getFederateHandle(wide(name))) == wide(name));
        CHECK(raises<NameNotFound>([&] { rti->getFederateHandle(L"nobody"); }));
        rti->listFederationExecutions();
        until(*rti, [&] { return fed.listed.count(L"Vehicles") > 0; }, "the federations listed");
        CHECK(fed.listed[L"Vehicles"] == L"HLAfloat64Time");
        CHECK(raises<ObjectInstanceNameNotReserved>([&] { rti->registerObjectInstance(vehicle, wide(name + "-vehicle")); }));

        AttributeHandleSet attributes{position};
        rti->publishObjectClassAttributes(vehicle, attributes);
        rti->subscribeObjectClassAttributes(vehicle, attributes);
        rti->enableTimeRegulation(HLAfloat64Interval(1.0));
        rti->enableTimeConstrained();
        until(*rti, [&] { return fed.counts["regulating"] && fed.counts["constrained"]; }, "time management");
        rti->reserveObjectInstanceName(wide(name + "-vehicle"));
        until(*rti, [&] { return !fed.reserved.empty(); }, "the name reserved");
        const ObjectInstanceHandle mine = rti->registerObjectInstance(vehicle, fed.reserved);
        CHECK(rti->getObjectInstanceName(mine) == fed.reserved);
        HLAfloat64Time start;
        rti->queryLogicalTime(start);
        std::cout << "{\"ready\": true, \"time\": " << start.getTime() << "}" << std::endl;

        until(*rti, [&] { return fed.counts["announce"] > 0; }, "go announced");
        rti->synchronizationPointAchieved(L"go");
        until(*rti, [&] { return fed.counts["synchronized"] > 0; }, "go synchronized");
        for (int step = 1; step <= steps; ++step) {
            const double t = start.getTime() + step;
            const std::string value = name + " " + std::to_string(step);
            AttributeHandleValueMap values;
            values[position] = VariableLengthData(value.data(), value.size());
            const MessageRetractionHandle sent = rti->updateAttributeValues(mine, values, VariableLengthData(), HLAfloat64Time(t));
            CHECK(rti->decodeMessageRetractionHandle(sent.encode()) == sent);
            rti->timeAdvanceRequest(HLAfloat64Time(t));
            until(*rti, [&] { return fed.granted == t; }, "a grant");
        }
        rti->resignFederationExecution(CANCEL_THEN_DELETE_THEN_DIVEST);
        rti->disconnect();
        std::cout << "{\"steps\": " << steps << ", \"reflections\": " << fed.reflections << ", \"late\": " << fed.late
                  << "}" << std::endl;
        return 0;
    } catch (Exception const& e) {
        std::wcerr << L"unexpected " << e.what() << std::endl;
        return 1;
    }
}
