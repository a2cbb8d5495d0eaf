// The C++ half of a mixed federation (tests/system/test_cpp_api.py runs the Python half): joins FEDERATION
// (made from tests/data/robot.fed) as NAME, exchanges a receive-order update and interaction with the
// Python federate, and a camera-size update (1 MiB) each way, then, from synchronization point "timed", runs
// STEPS steps of a TSO lockstep with it
// (regulating and constrained, lookahead 1: an update of robot.location at t, then timeAdvanceRequest(t)).
// Prints {"ready": true} once set up, and at the end one JSON line: the steps, the updates reflected, and
// the grants not preceded by the peer's update at their time.
#include <iostream>
#include <memory>
#include <string>

#include "recorder.hh"

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: mixed_federate FEDERATION NAME STEPS\n";
        return 2;
    }
    const std::string name = argv[2];
    const int steps = std::stoi(argv[3]);
    try {
        RTI::RTIambassador rtia;
        Recorder amb;
        rtia.joinFederationExecution(name.c_str(), argv[1], &amb);
        const auto until = [&](const std::function<bool()>& p, const char* what) { tick_until(p, {&rtia}, what, 60.0); };
        const auto robot = rtia.getObjectClassHandle("robot");
        const auto location = rtia.getAttributeHandle("location", robot);
        const auto command = rtia.getInteractionClassHandle("command");
        const auto value = rtia.getParameterHandle("value", command);
        rtia.publishObjectClass(robot, *attribute_set({location}));
        rtia.subscribeObjectClassAttributes(robot, *attribute_set({location}));
        rtia.publishInteractionClass(command);
        rtia.subscribeInteractionClass(command);
        const auto object = rtia.registerObjectInstance(robot, name.c_str());
        round_trip(rtia);
        std::cout << "{\"ready\": true}" << std::endl;

        until([&] { return amb.count("announceSynchronizationPoint") > 0; }, "start announced");
        rtia.synchronizationPointAchieved("start");
        until([&] { return amb.count("federationSynchronized") > 0; }, "start synchronized");

        // Both ways, in receive order: an update and an interaction each.
        const std::string hello = "hello from " + name;
        rtia.updateAttributeValues(object, *attribute_values(location, hello), "ro");
        std::unique_ptr<RTI::ParameterHandleValuePairSet> parameters(RTI::ParameterSetFactory::create(1));
        parameters->add(value, hello.data(), hello.size());
        rtia.sendInteraction(command, *parameters, "ro");
        until([&] {
            bool reflected = false, received = false;
            for (const auto* e : amb.saw("reflectAttributeValues")) reflected |= e->values.count(location) && e->values.at(location) == "hello from python";
            for (const auto* e : amb.saw("receiveInteraction")) received |= e->values.count(value) && e->values.at(value) == "hello from python";
            return reflected && received;
        }, "the Python federate's update and interaction");
        // A camera frame each way: sent from where it is, received in the block it was read into.
        std::string camera(1 << 20, '\0');
        for (std::size_t i = 0; i < camera.size(); ++i) camera[i] = static_cast<char>(i % 251);
        rtia.updateAttributeValues(object, *attribute_values(location, camera), "camera");
        until([&] {
            for (const auto* e : amb.saw("reflectAttributeValues"))
                if (e->values.count(location) && e->values.at(location) == camera) return true;
            return false;
        }, "the Python federate's camera frame");

        rtia.enableTimeRegulation(RTIfedTime(0.0), RTIfedTime(1.0));
        rtia.enableTimeConstrained();
        until([&] { return amb.count("timeRegulationEnabled") && amb.count("timeConstrainedEnabled"); }, "time management");
        // The Python federate registers "timed" once its own time management is on: both are on at the synchronization.
        until([&] { return amb.count("announceSynchronizationPoint") == 2; }, "timed announced");
        rtia.synchronizationPointAchieved("timed");
        until([&] { return amb.count("federationSynchronized") == 2; }, "timed synchronized");
        for (int step = 1; step <= steps; ++step) {
            const RTIfedTime t(step);
            rtia.updateAttributeValues(object, *attribute_values(location, name + " " + std::to_string(step)), t, "");
            rtia.timeAdvanceRequest(t);
            until([&] { return !amb.grants().empty() && amb.grants().back() == step; }, "the grant");
        }

        // Every grant at t came after the peer's update at t (the callbacks in the order delivered).
        int reflections = 0, late = 0;
        double last_reflected = 0;
        for (const auto& e : amb.events) {
            if (e.name == "reflectAttributeValues" && !std::isnan(e.time)) {
                ++reflections;
                last_reflected = e.time;
            } else if (e.name == "timeAdvanceGrant" && last_reflected != e.time) {
                ++late;
            }
        }
        rtia.resignFederationExecution(RTI::DELETE_OBJECTS_AND_RELEASE_ATTRIBUTES);
        print_lockstep_summary(steps, reflections, late);
    } catch (RTI::Exception& e) {
        std::cerr << "mixed_federate: " << e << "\n";
        return 1;
    }
    return 0;
}
