// An HLA 1.3 C++ federate in a lockstep with federates of both APIs (tests/rti/test_rti1516e_cpp.py): joins
// FEDERATION (the Vehicles federation of tests/data/rti1516e, made from XML modules) as NAME, regulating and
// constrained with lookahead 1, and from synchronization point "go" runs STEPS steps: its vehicle's position
// at t, then timeAdvanceRequest(t). Prints {"ready": true} once set up and, at the end, one JSON line: the
// steps, the timestamped reflections, and the grants that came before all PEERS others' updates at their time.
#include <iostream>
#include <map>
#include <string>

#include "recorder.hh"

int main(int argc, char** argv) {
    if (argc != 5) return std::fprintf(stderr, "usage: lockstep_federate FEDERATION NAME STEPS PEERS\n"), 2;
    const std::string name = argv[2];
    const int steps = std::stoi(argv[3]);
    const int peers = std::stoi(argv[4]);
    try {
        TestFederate f(name, argv[1]);
        RTI::RTIambassador& rtia = f.rtia;
        const auto vehicle = rtia.getObjectClassHandle("Vehicle");
        const auto position = rtia.getAttributeHandle("position", vehicle);
        rtia.publishObjectClass(vehicle, *attribute_set({position}));
        rtia.subscribeObjectClassAttributes(vehicle, *attribute_set({position}));
        rtia.enableTimeRegulation(RTIfedTime(0.0), RTIfedTime(1.0));
        rtia.enableTimeConstrained();
        f.until([&] { return f.amb.count("timeRegulationEnabled") && f.amb.count("timeConstrainedEnabled"); },
                "time management");
        const auto object = rtia.registerObjectInstance(vehicle, (name + "-vehicle").c_str());
        std::cout << "{\"ready\": true}" << std::endl;

        f.until([&] { return f.amb.count("announceSynchronizationPoint") > 0; }, "go announced");
        rtia.synchronizationPointAchieved("go");
        f.until([&] { return f.amb.count("federationSynchronized") > 0; }, "go synchronized");
        std::map<double, int> reflected_at;  // the timestamped reflections by time, counted as they are delivered
        int late = 0, reflections = 0;
        std::size_t seen = 0;
        for (int step = 1; step <= steps; ++step) {
            const RTIfedTime t(step);
            rtia.updateAttributeValues(object, *attribute_values(position, name + " " + std::to_string(step)), t, "");
            rtia.timeAdvanceRequest(t);
            bool granted = false;
            f.until([&] {
                for (; seen < f.amb.events.size() && !granted; ++seen) {
                    const Event& e = f.amb.events[seen];
                    if (e.name == "reflectAttributeValues" && !std::isnan(e.time)) {
                        ++reflected_at[e.time];
                        ++reflections;
                    }
                    if (e.name == "timeAdvanceGrant") {
                        granted = e.time == step;
                        late += reflected_at[e.time] != peers;
                    }
                }
                return granted;
            }, "the grant");
        }
        rtia.resignFederationExecution(RTI::DELETE_OBJECTS_AND_RELEASE_ATTRIBUTES);
        print_lockstep_summary(steps, reflections, late);
        return 0;
    } catch (RTI::Exception& e) {
        std::cerr << "lockstep_federate: " << e << "\n";
        return 1;
    }
}
