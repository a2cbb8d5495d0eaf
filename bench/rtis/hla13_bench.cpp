// One benchmark program written against the HLA 1.3 C++ API only, compiled unchanged against hlacore,
// OpenRTI and CERTI 3.5.1 (bench/three_rtis.py compiles it against each install given; bench/test_three_rtis.py
// runs it).
// Every federate is its own process; the federation uses hlacore's robot.fed (robot.location, 8-byte values).
//
//   hla13_bench WORKLOAD FEDERATION FED create|join NAME FEDERATES N M
//
//   lockstep (FEDERATES = K, N steps after M warm-up steps):
//       K federates regulating and constrained (lookahead 1); a step is an update of robot.location at t+1
//       (TSO), timeAdvanceRequest(t+1), tick until the grant. Each checks that every grant came after the
//       K-1 others' updates at its time. The creator prints {"samples_ns": [...]}, one per step after WARMUP.
//   pingpong (FEDERATES = 2, N round trips after M warm-up ones):
//       Two federates without time management: the creator updates, the other reflects and updates back;
//       the creator prints the round trips after WARMUP as {"samples_ns": [...]}.
//   throughput (FEDERATES = 2, M bursts of N updates):
//       The creator sends bursts of BURST receive-order updates as fast as the RTI takes them; the other
//       counts them and answers each complete burst with an update. The creator prints the delivered rate
//       of each burst, {"rates": [...]} in updates per second.
//
// The federates first discover each other and synchronize ("ready"); with time management they then turn on
// asynchronous delivery (so that a constrained CERTI federate gets the synchronization callbacks outside a
// time advance) and synchronize again ("timed"); at the end they synchronize ("done") before resigning, which
// OpenRTI needs to deliver a resigning federate's last update. Callbacks come from tick(1.0, 1.0): block until
// one comes, deliver what is ready, return.
#include <RTI.hh>
#include <fedtime.hh>
#include <NullFederateAmbassador.hh>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

#define NOTHROW throw()

namespace {

using Clock = std::chrono::steady_clock;

[[noreturn]] void fail(const std::string& why) {
    std::cerr << "hla13_bench: " << why << std::endl;
    std::exit(1);
}

class Ambassador : public NullFederateAmbassador {
public:
    std::set<std::string> announced, synchronized;
    std::set<RTI::ObjectHandle> discovered;
    bool regulating = false, constrained = false, granted = false;
    double grant_time = 0;
    long reflections = 0;
    std::map<double, int> timed_reflections;  // updates reflected per timestamp
    int late = 0;                             // TSO reflections at or below the last grant

    void announceSynchronizationPoint(const char* label, const char*) NOTHROW { announced.insert(label); }
    void federationSynchronized(const char* label) NOTHROW { synchronized.insert(label); }
    void discoverObjectInstance(RTI::ObjectHandle object, RTI::ObjectClassHandle, const char*) NOTHROW {
        discovered.insert(object);
    }
    void reflectAttributeValues(RTI::ObjectHandle, const RTI::AttributeHandleValuePairSet&, const RTI::FedTime& time,
                                const char*, RTI::EventRetractionHandle) NOTHROW {
        const double t = static_cast<const RTIfedTime&>(time).getTime();
        if (t <= grant_time) ++late;
        ++timed_reflections[t];
        ++reflections;
    }
    void reflectAttributeValues(RTI::ObjectHandle, const RTI::AttributeHandleValuePairSet&, const char*) NOTHROW {
        ++reflections;
    }
    void timeRegulationEnabled(const RTI::FedTime&) NOTHROW { regulating = true; }
    void timeConstrainedEnabled(const RTI::FedTime&) NOTHROW { constrained = true; }
    void timeAdvanceGrant(const RTI::FedTime& time) NOTHROW {
        granted = true;
        grant_time = static_cast<const RTIfedTime&>(time).getTime();
    }
};

struct Federate {
    RTI::RTIambassador rtia;
    Ambassador amb;
    std::string federation;
    bool creator = false;
    RTI::ObjectHandle object = 0;
    RTI::AttributeHandle location = 0;
    RTI::AttributeHandleValuePairSet* value = nullptr;

    // Ticks until `done()`, failing after a minute.
    void until(const std::function<bool()>& done, const char* what) {
        const auto deadline = Clock::now() + std::chrono::seconds(60);
        while (!done()) {
            if (Clock::now() > deadline) fail(std::string("no ") + what + " within 60 s");
            rtia.tick(1.0, 1.0);
        }
    }

    // Creates (the creator) and joins, publishes and subscribes robot.location, registers NAME's robot and
    // waits until it has discovered the others' robots; then synchronizes "ready".
    void join(const char* fed, const char* name, int others) {
        if (creator) {
            try {
                rtia.createFederationExecution(federation.c_str(), fed);
            } catch (RTI::FederationExecutionAlreadyExists&) {
            }
        }
        for (int attempt = 0;; ++attempt) {
            try {
                rtia.joinFederationExecution(name, federation.c_str(), &amb);
                break;
            } catch (RTI::FederationExecutionDoesNotExist&) {
                if (attempt == 400) throw;
                usleep(25000);
            }
        }
        const RTI::ObjectClassHandle robot = rtia.getObjectClassHandle("robot");
        location = rtia.getAttributeHandle("location", robot);
        RTI::AttributeHandleSet* attributes = RTI::AttributeHandleSetFactory::create(1);
        attributes->add(location);
        rtia.publishObjectClass(robot, *attributes);
        rtia.subscribeObjectClassAttributes(robot, *attributes, RTI::RTI_TRUE);
        delete attributes;
        object = rtia.registerObjectInstance(robot, name);
        value = RTI::AttributeSetFactory::create(1);
        const char payload[8] = {0, 1, 2, 3, 4, 5, 6, 7};
        value->add(location, payload, sizeof(payload));
        until([&] { return static_cast<int>(amb.discovered.size()) >= others; }, "discovery of the others");
        synchronize("ready");
    }

    // The creator registers `label`; each achieves it once announced; returns when the federation is synchronized.
    void synchronize(const char* label) {
        if (creator) rtia.registerFederationSynchronizationPoint(label, "");
        until([&] { return amb.announced.count(label) > 0; }, label);
        rtia.synchronizationPointAchieved(label);
        until([&] { return amb.synchronized.count(label) > 0; }, label);
    }

    void enable_time_management() {
        RTIfedTime zero(0.0), lookahead(1.0);
        rtia.enableTimeRegulation(zero, lookahead);
        until([&] { return amb.regulating; }, "timeRegulationEnabled");
        rtia.enableTimeConstrained();
        until([&] { return amb.constrained; }, "timeConstrainedEnabled");
        rtia.enableAsynchronousDelivery();
        synchronize("timed");
    }

    void leave() {
        synchronize("done");
        delete value;
        rtia.resignFederationExecution(RTI::DELETE_OBJECTS_AND_RELEASE_ATTRIBUTES);
        if (!creator) return;
        for (int attempt = 0;; ++attempt) {
            try {
                rtia.destroyFederationExecution(federation.c_str());
                return;
            } catch (RTI::FederatesCurrentlyJoined&) {
                if (attempt == 400) throw;
                usleep(25000);
            }
        }
    }
};

long long since(Clock::time_point start) {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - start).count();
}

void print_samples(const char* key, const std::vector<double>& samples) {
    std::cout << "{\"" << key << "\": [";
    for (std::size_t i = 0; i < samples.size(); ++i) std::cout << (i ? ", " : "") << samples[i];
    std::cout << "]}" << std::endl;
}

void lockstep(Federate& f, int k, int steps, int warmup) {
    f.enable_time_management();
    std::vector<double> samples;
    int missing = 0;
    for (int step = 1; step <= warmup + steps; ++step) {
        const auto start = Clock::now();
        RTIfedTime t(static_cast<double>(step));
        f.rtia.updateAttributeValues(f.object, *f.value, t, "");
        f.amb.granted = false;
        f.rtia.timeAdvanceRequest(t);
        f.until([&] { return f.amb.granted; }, "timeAdvanceGrant");
        if (f.amb.timed_reflections[step] != k - 1) ++missing;
        if (step > warmup) samples.push_back(static_cast<double>(since(start)));
    }
    if (missing || f.amb.late) fail(std::to_string(missing) + " grants came before the others' updates, " +
                                    std::to_string(f.amb.late) + " updates came late");
    f.leave();
    if (f.creator) print_samples("samples_ns", samples);
}

void pingpong(Federate& f, int rounds, int warmup) {
    std::vector<double> samples;
    for (int round = 1; round <= warmup + rounds; ++round) {
        if (f.creator) {
            const auto start = Clock::now();
            f.rtia.updateAttributeValues(f.object, *f.value, "");
            f.until([&] { return f.amb.reflections >= round; }, "the echo");
            if (round > warmup) samples.push_back(static_cast<double>(since(start)));
        } else {
            f.until([&] { return f.amb.reflections >= round; }, "the ping");
            f.rtia.updateAttributeValues(f.object, *f.value, "");
        }
    }
    f.leave();
    if (f.creator) print_samples("samples_ns", samples);
}

void throughput(Federate& f, long burst, int bursts) {
    std::vector<double> rates;
    for (int b = 1; b <= bursts; ++b) {
        if (f.creator) {
            const auto start = Clock::now();
            for (long i = 0; i < burst; ++i) f.rtia.updateAttributeValues(f.object, *f.value, "");
            f.until([&] { return f.amb.reflections >= b; }, "the burst's acknowledgement");
            rates.push_back(static_cast<double>(burst) * 1e9 / static_cast<double>(since(start)));
        } else {
            f.until([&] { return f.amb.reflections >= b * burst; }, "the whole burst");
            f.rtia.updateAttributeValues(f.object, *f.value, "");
        }
    }
    f.leave();
    if (f.creator) print_samples("rates", rates);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 9 || (std::strcmp(argv[4], "create") != 0 && std::strcmp(argv[4], "join") != 0)) {
        std::cerr << "usage: hla13_bench lockstep|pingpong|throughput FEDERATION FED create|join NAME FEDERATES N M\n";
        return 2;
    }
    const std::string workload = argv[1];
    try {
        Federate f;
        f.federation = argv[2];
        f.creator = std::strcmp(argv[4], "create") == 0;
        const int federates = std::atoi(argv[6]);
        const long n = std::atol(argv[7]), m = std::atol(argv[8]);
        if (workload != "lockstep" && workload != "pingpong" && workload != "throughput")
            fail("unknown workload " + workload);
        if (federates < 2 || (workload != "lockstep" && federates != 2)) fail("wrong number of federates");
        f.join(argv[3], argv[5], federates - 1);
        if (workload == "lockstep") {
            lockstep(f, federates, static_cast<int>(n), static_cast<int>(m));
        } else if (workload == "pingpong") {
            pingpong(f, static_cast<int>(n), static_cast<int>(m));
        } else {
            throughput(f, n, static_cast<int>(m));
        }
    } catch (RTI::Exception& e) {
        fail(std::string(e._name ? e._name : "RTI::Exception") + ": " + (e._reason ? e._reason : ""));
    }
    return 0;
}
