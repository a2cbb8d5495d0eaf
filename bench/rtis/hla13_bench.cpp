// The benchmark program on the HLA 1.3 C++ API only, compiled unchanged against hlacore, OpenRTI and CERTI 3.5.1
// (bench/three_rtis.py compiles it against each install given; bench/test_three_rtis.py runs it). The command
// line, the protocol and the workloads are workloads.hh's, shared with its IEEE 1516-2010 twin
// rti1516e_bench.cpp; this file is the HLA 1.3 calls. The FOM is hlacore's robot.fed. Callbacks come from
// tick(1.0, 1.0).
#include <RTI.hh>
#include <fedtime.hh>
#include <NullFederateAmbassador.hh>

#include <memory>
#include <string>

#include "workloads.hh"

#define NOTHROW throw()

namespace {

class Ambassador : public NullFederateAmbassador {
public:
    bench::Received& got;

    explicit Ambassador(bench::Received& received) : got(received) {}
    void announceSynchronizationPoint(const char* label, const char*) NOTHROW { got.announced.insert(label); }
    void federationSynchronized(const char* label) NOTHROW { got.synchronized.insert(label); }
    void discoverObjectInstance(RTI::ObjectHandle, RTI::ObjectClassHandle, const char*) NOTHROW { ++got.discovered; }
    void reflectAttributeValues(RTI::ObjectHandle, const RTI::AttributeHandleValuePairSet&, const RTI::FedTime& time,
                                const char*, RTI::EventRetractionHandle) NOTHROW {
        got.reflect_at(static_cast<const RTIfedTime&>(time).getTime());
    }
    void reflectAttributeValues(RTI::ObjectHandle, const RTI::AttributeHandleValuePairSet&, const char*) NOTHROW {
        ++got.reflections;
    }
    void timeRegulationEnabled(const RTI::FedTime&) NOTHROW { got.regulating = true; }
    void timeConstrainedEnabled(const RTI::FedTime&) NOTHROW { got.constrained = true; }
    void timeAdvanceGrant(const RTI::FedTime& time) NOTHROW { got.grant(static_cast<const RTIfedTime&>(time).getTime()); }
};

class Federate : public bench::Federate {
public:
    RTI::RTIambassador rtia;
    Ambassador amb{got};
    std::string federation;
    RTI::ObjectHandle object = 0;
    std::unique_ptr<RTI::AttributeHandleValuePairSet> value;

    void join(const std::string& name, const char* fed, const char* federate) override {
        federation = name;
        if (creator) {
            try {
                rtia.createFederationExecution(federation.c_str(), fed);
            } catch (RTI::FederationExecutionAlreadyExists&) {
            }
        }
        bench::retry<RTI::FederationExecutionDoesNotExist>(
            [&] { rtia.joinFederationExecution(federate, federation.c_str(), &amb); });
        const RTI::ObjectClassHandle robot = rtia.getObjectClassHandle("robot");
        const RTI::AttributeHandle location = rtia.getAttributeHandle("location", robot);
        std::unique_ptr<RTI::AttributeHandleSet> attributes(RTI::AttributeHandleSetFactory::create(1));
        attributes->add(location);
        rtia.publishObjectClass(robot, *attributes);
        rtia.subscribeObjectClassAttributes(robot, *attributes, RTI::RTI_TRUE);
        object = rtia.registerObjectInstance(robot, federate);
        value.reset(RTI::AttributeSetFactory::create(1));
        const char payload[8] = {0, 1, 2, 3, 4, 5, 6, 7};
        value->add(location, payload, sizeof(payload));
    }
    void tick() override { rtia.tick(1.0, 1.0); }
    void register_point(const std::string& label) override {
        rtia.registerFederationSynchronizationPoint(label.c_str(), "");
    }
    void achieve(const std::string& label) override { rtia.synchronizationPointAchieved(label.c_str()); }
    void enable_regulation() override { rtia.enableTimeRegulation(RTIfedTime(0.0), RTIfedTime(1.0)); }
    void enable_constrained() override { rtia.enableTimeConstrained(); }
    void enable_asynchronous_delivery() override { rtia.enableAsynchronousDelivery(); }
    void update() override { rtia.updateAttributeValues(object, *value, ""); }
    void update_at(double time) override { rtia.updateAttributeValues(object, *value, RTIfedTime(time), ""); }
    void advance(double time) override { rtia.timeAdvanceRequest(RTIfedTime(time)); }
    void resign() override {
        rtia.resignFederationExecution(RTI::DELETE_OBJECTS_AND_RELEASE_ATTRIBUTES);
        if (creator) bench::retry<RTI::FederatesCurrentlyJoined>([&] { rtia.destroyFederationExecution(federation.c_str()); });
    }
};

}  // namespace

int main(int argc, char** argv) {
    try {
        return bench::run(argc, argv, "hla13_bench", [] { return std::unique_ptr<bench::Federate>(new Federate); });
    } catch (RTI::Exception& e) {
        bench::fail(std::string(e._name ? e._name : "RTI::Exception") + ": " + (e._reason ? e._reason : ""));
    }
}
