// The benchmark program on the IEEE 1516-2010 C++ API only (SISO's DLC headers), the twin of hla13_bench.cpp:
// the same command line, protocol and workloads (workloads.hh), compiled unchanged against hlacore's
// librti1516e and OpenRTI's (bench/three_rtis.py). The FOM is bench/rtis/robot.xml, robot.location as in
// robot.fed; times are HLAfloat64Time. Callbacks come from evokeMultipleCallbacks(1.0, 1.0), as hla13_bench's
// from tick(1.0, 1.0). FEDERATION is a name, the RTI found where its defaults say (hlacore: $HLACORE_RTIG), or
// OpenRTI's rti://HOST:PORT/NAME: the program connects to rti://HOST:PORT and joins NAME.
#include <RTI/NullFederateAmbassador.h>
#include <RTI/RTI1516.h>
#include <RTI/time/HLAfloat64Interval.h>
#include <RTI/time/HLAfloat64Time.h>

#include <memory>
#include <string>

#include "workloads.hh"

using namespace rti1516e;

namespace {

std::wstring wide(const std::string& s) { return std::wstring(s.begin(), s.end()); }
std::string narrow(const std::wstring& s) { return std::string(s.begin(), s.end()); }
double seconds(const LogicalTime& time) { return dynamic_cast<const HLAfloat64Time&>(time).getTime(); }

class Ambassador : public NullFederateAmbassador {
public:
    bench::Received& got;

    explicit Ambassador(bench::Received& received) : got(received) {}
    void announceSynchronizationPoint(const std::wstring& label, const VariableLengthData&) override {
        got.announced.insert(narrow(label));
    }
    void federationSynchronized(const std::wstring& label, const FederateHandleSet&) override {
        got.synchronized.insert(narrow(label));
    }
    // An RTI calls one of the two (hlacore the one without the producer, the standard leaving it open).
    void discoverObjectInstance(ObjectInstanceHandle, ObjectClassHandle, const std::wstring&) override { ++got.discovered; }
    void discoverObjectInstance(ObjectInstanceHandle, ObjectClassHandle, const std::wstring&, FederateHandle) override {
        ++got.discovered;
    }
    void reflectAttributeValues(ObjectInstanceHandle, const AttributeHandleValueMap&, const VariableLengthData&,
                                OrderType, TransportationType, SupplementalReflectInfo) override {
        ++got.reflections;
    }
    // Timestamped, with and without a retraction handle (which one is the RTI's choice).
    void reflectAttributeValues(ObjectInstanceHandle, const AttributeHandleValueMap&, const VariableLengthData&,
                                OrderType, TransportationType, const LogicalTime& time, OrderType,
                                SupplementalReflectInfo) override {
        got.reflect_at(seconds(time));
    }
    void reflectAttributeValues(ObjectInstanceHandle, const AttributeHandleValueMap&, const VariableLengthData&,
                                OrderType, TransportationType, const LogicalTime& time, OrderType,
                                MessageRetractionHandle, SupplementalReflectInfo) override {
        got.reflect_at(seconds(time));
    }
    void timeRegulationEnabled(const LogicalTime&) override { got.regulating = true; }
    void timeConstrainedEnabled(const LogicalTime&) override { got.constrained = true; }
    void timeAdvanceGrant(const LogicalTime& time) override { got.grant(seconds(time)); }
};

class Federate : public bench::Federate {
public:
    std::unique_ptr<RTIambassador> rti = RTIambassadorFactory().createRTIambassador();
    Ambassador amb{got};
    std::wstring federation;
    ObjectInstanceHandle object;
    AttributeHandleValueMap value;

    void join(const std::string& name, const char* fom, const char* federate) override {
        const std::string::size_type path = name.rfind('/');
        const bool url = name.compare(0, 6, "rti://") == 0 && path > 5;
        rti->connect(amb, HLA_EVOKED, url ? wide(name.substr(0, path)) : L"");
        federation = wide(url ? name.substr(path + 1) : name);
        if (creator) {
            try {
                rti->createFederationExecution(federation, wide(fom));
            } catch (FederationExecutionAlreadyExists&) {
            }
        }
        bench::retry<FederationExecutionDoesNotExist>([&] { rti->joinFederationExecution(wide(federate), L"bench", federation); });
        const ObjectClassHandle robot = rti->getObjectClassHandle(L"robot");
        const AttributeHandle location = rti->getAttributeHandle(robot, L"location");
        rti->publishObjectClassAttributes(robot, {location});
        rti->subscribeObjectClassAttributes(robot, {location});
        object = rti->registerObjectInstance(robot);
        const char payload[8] = {0, 1, 2, 3, 4, 5, 6, 7};
        value[location] = VariableLengthData(payload, sizeof(payload));
    }
    void tick() override { rti->evokeMultipleCallbacks(1.0, 1.0); }
    void register_point(const std::string& label) override {
        rti->registerFederationSynchronizationPoint(wide(label), VariableLengthData());
    }
    void achieve(const std::string& label) override { rti->synchronizationPointAchieved(wide(label)); }
    void enable_regulation() override { rti->enableTimeRegulation(HLAfloat64Interval(1.0)); }
    void enable_constrained() override { rti->enableTimeConstrained(); }
    void enable_asynchronous_delivery() override { rti->enableAsynchronousDelivery(); }
    void update() override { rti->updateAttributeValues(object, value, VariableLengthData()); }
    void update_at(double time) override {
        rti->updateAttributeValues(object, value, VariableLengthData(), HLAfloat64Time(time));
    }
    void advance(double time) override { rti->timeAdvanceRequest(HLAfloat64Time(time)); }
    void resign() override {
        rti->resignFederationExecution(DELETE_OBJECTS_THEN_DIVEST);
        if (creator) bench::retry<FederatesCurrentlyJoined>([&] { rti->destroyFederationExecution(federation); });
        rti->disconnect();
    }
};

}  // namespace

int main(int argc, char** argv) {
    try {
        return bench::run(argc, argv, "rti1516e_bench", [] { return std::unique_ptr<bench::Federate>(new Federate); });
    } catch (Exception& e) {
        bench::fail(narrow(e.what()));
    }
}
