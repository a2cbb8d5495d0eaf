// What the benchmark programs of bench/rtis share, written once: hla13_bench.cpp (the HLA 1.3 C++ API) and
// rti1516e_bench.cpp (the IEEE 1516-2010 one) each implement `Federate` with their API and hand it to run(),
// which holds the command line, the protocol, the three workloads, their checks and their JSON output.
// Header-only and C++14, so that each program stays one file that compiles against any RTI (CERTI's HLA 1.3
// headers need C++14). Every federate is its own process; the federation's FOM has robot.location (8-byte values).
//
//   PROGRAM WORKLOAD FEDERATION FOM create|join NAME FEDERATES N M
//
//   lockstep (FEDERATES = K, N steps after M warm-up steps):
//       K federates regulating and constrained (lookahead 1); a step is an update of robot.location at t+1
//       (TSO), a time advance request to t+1, callbacks until the grant. Each checks that every grant came after
//       the K-1 others' updates at its time. The creator prints {"samples_ns": [...]}, one per step after WARMUP.
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
// OpenRTI needs to deliver a resigning federate's last update. Callbacks come from Federate::tick(): block
// until one comes (1 s at most), deliver what is ready, return.
#ifndef BENCH_RTIS_WORKLOADS_HH
#define BENCH_RTIS_WORKLOADS_HH

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

namespace bench {

using Clock = std::chrono::steady_clock;

// The program's name, for its messages.
inline std::string& program() {
    static std::string name = "bench";
    return name;
}

[[noreturn]] inline void fail(const std::string& why) {
    std::cerr << program() << ": " << why << std::endl;
    std::exit(1);
}

// Calls `call` until it does not throw E, 400 times at most, 25 ms apart: the federation is being created by
// another process, or its other federates are still resigning.
template <class E, class Call>
void retry(Call call) {
    for (int attempt = 0;; ++attempt) {
        try {
            call();
            return;
        } catch (E&) {
            if (attempt == 400) throw;
            usleep(25000);
        }
    }
}

// What the callbacks told, which the protocol and the workloads wait on: each program's federate ambassador
// records into it.
struct Received {
    std::set<std::string> announced, synchronized;
    int discovered = 0;
    bool regulating = false, constrained = false, granted = false;
    double grant_time = 0;
    long reflections = 0;
    std::map<double, int> timed_reflections;  // updates reflected per timestamp
    int late = 0;                             // TSO reflections at or below the last grant

    void reflect_at(double time) {
        if (time <= grant_time) ++late;
        ++timed_reflections[time];
        ++reflections;
    }
    void grant(double time) {
        granted = true;
        grant_time = time;
    }
};

// One federate through its RTI's API: the calls the protocol and the workloads make.
class Federate {
public:
    Received got;
    bool creator = false;

    virtual ~Federate() noexcept(false) = default;  // an HLA 1.3 RTIambassador's destructor may throw
    // Creates FEDERATION on FOM (the creator) and joins it as NAME, publishes and subscribes robot.location and
    // registers a robot.
    virtual void join(const std::string& federation, const char* fom, const char* name) = 0;
    virtual void tick() = 0;  // blocks until a callback comes (1 s at most), delivers what is ready
    virtual void register_point(const std::string& label) = 0;
    virtual void achieve(const std::string& label) = 0;
    virtual void enable_regulation() = 0;  // lookahead 1
    virtual void enable_constrained() = 0;
    virtual void enable_asynchronous_delivery() = 0;
    virtual void update() = 0;               // receive order
    virtual void update_at(double time) = 0;  // timestamped
    virtual void advance(double time) = 0;    // time advance request
    virtual void resign() = 0;                // and the creator destroys the federation

    // Ticks until `done()`, failing after a minute.
    void until(const std::function<bool()>& done, const std::string& what) {
        const auto deadline = Clock::now() + std::chrono::seconds(60);
        while (!done()) {
            if (Clock::now() > deadline) fail("no " + what + " within 60 s");
            tick();
        }
    }

    // The creator registers `label`; each achieves it once announced; returns when the federation is synchronized.
    void synchronize(const std::string& label) {
        if (creator) register_point(label);
        until([&] { return got.announced.count(label) > 0; }, label);
        achieve(label);
        until([&] { return got.synchronized.count(label) > 0; }, label);
    }
};

inline long long since(Clock::time_point start) {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - start).count();
}

inline void print_samples(const char* key, const std::vector<double>& samples) {
    std::cout << "{\"" << key << "\": [";
    for (std::size_t i = 0; i < samples.size(); ++i) std::cout << (i ? ", " : "") << samples[i];
    std::cout << "]}" << std::endl;
}

inline void lockstep(Federate& f, int k, int steps, int warmup, std::vector<double>& samples) {
    f.enable_regulation();
    f.until([&] { return f.got.regulating; }, "timeRegulationEnabled");
    f.enable_constrained();
    f.until([&] { return f.got.constrained; }, "timeConstrainedEnabled");
    f.enable_asynchronous_delivery();
    f.synchronize("timed");
    int missing = 0;
    for (int step = 1; step <= warmup + steps; ++step) {
        const auto start = Clock::now();
        f.update_at(step);
        f.got.granted = false;
        f.advance(step);
        f.until([&] { return f.got.granted; }, "timeAdvanceGrant");
        if (f.got.timed_reflections[step] != k - 1) ++missing;
        if (step > warmup) samples.push_back(static_cast<double>(since(start)));
    }
    if (missing || f.got.late) fail(std::to_string(missing) + " grants came before the others' updates, " +
                                    std::to_string(f.got.late) + " updates came late");
}

inline void pingpong(Federate& f, int rounds, int warmup, std::vector<double>& samples) {
    for (int round = 1; round <= warmup + rounds; ++round) {
        if (f.creator) {
            const auto start = Clock::now();
            f.update();
            f.until([&] { return f.got.reflections >= round; }, "the echo");
            if (round > warmup) samples.push_back(static_cast<double>(since(start)));
        } else {
            f.until([&] { return f.got.reflections >= round; }, "the ping");
            f.update();
        }
    }
}

inline void throughput(Federate& f, long burst, int bursts, std::vector<double>& rates) {
    for (int b = 1; b <= bursts; ++b) {
        if (f.creator) {
            const auto start = Clock::now();
            for (long i = 0; i < burst; ++i) f.update();
            f.until([&] { return f.got.reflections >= b; }, "the burst's acknowledgement");
            rates.push_back(static_cast<double>(burst) * 1e9 / static_cast<double>(since(start)));
        } else {
            f.until([&] { return f.got.reflections >= b * burst; }, "the whole burst");
            f.update();
        }
    }
}

// The program: checks the command line, makes the federate (`make`, after the check: an HLA 1.3 ambassador
// connects when made), joins, waits for the others' robots, runs the workload, leaves, and the creator prints
// the samples. Returns the exit status; the API's exceptions go to the caller.
inline int run(int argc, char** argv, const char* name, const std::function<std::unique_ptr<Federate>()>& make) {
    program() = name;
    if (argc != 9 || (std::strcmp(argv[4], "create") != 0 && std::strcmp(argv[4], "join") != 0)) {
        std::cerr << "usage: " << name << " lockstep|pingpong|throughput FEDERATION FOM create|join NAME FEDERATES N M\n";
        return 2;
    }
    const std::string workload = argv[1];
    const int federates = std::atoi(argv[6]);
    const long n = std::atol(argv[7]), m = std::atol(argv[8]);
    if (workload != "lockstep" && workload != "pingpong" && workload != "throughput") fail("unknown workload " + workload);
    if (federates < 2 || (workload != "lockstep" && federates != 2)) fail("wrong number of federates");
    std::unique_ptr<Federate> f = make();
    f->creator = std::strcmp(argv[4], "create") == 0;
    f->join(argv[2], argv[3], argv[5]);
    f->until([&] { return f->got.discovered >= federates - 1; }, "discovery of the others");
    f->synchronize("ready");
    std::vector<double> samples;
    if (workload == "lockstep") {
        lockstep(*f, federates, static_cast<int>(n), static_cast<int>(m), samples);
    } else if (workload == "pingpong") {
        pingpong(*f, static_cast<int>(n), static_cast<int>(m), samples);
    } else {
        throughput(*f, n, static_cast<int>(m), samples);
    }
    f->synchronize("done");
    f->resign();
    if (f->creator) print_samples(workload == "throughput" ? "rates" : "samples_ns", samples);
    return 0;
}

}  // namespace bench

#endif
