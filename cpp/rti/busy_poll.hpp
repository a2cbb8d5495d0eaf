// Busy polling (opt-in: ClientOptions::busy_poll_us, GatewayOptions::busy_poll_us): before a wait sleeps,
// poll for a while without sleeping. A process that sleeps in poll() is woken by the kernel when its peer
// writes, and on a machine whose idle cores halt (a VM's vCPUs above all) that wake-up costs tens of µs per
// message; a process still polling reads the message as soon as it lands. The price is a core kept busy
// while waiting, so it pays where the processes that take turns are fewer than the cores.
#pragma once

#include <sched.h>

#include <chrono>
#include <cstdint>
#include <string>

namespace hlacore {

// The longest spin accepted (µs): longer ones keep a core busy for nothing a sleep would not do as well.
constexpr std::uint32_t kMaxBusyPollUs = 100000;

// Why `us` is not an acceptable spin ("" when it is).
inline std::string busy_poll_error(long long us) {
    if (us >= 0 && us <= kMaxBusyPollUs) return "";
    return "busy polling must be a whole number of µs between 0 and " + std::to_string(kMaxBusyPollUs) + ", not " +
           std::to_string(us);
}

// Calls `poll` (non-blocking: > 0 ready, 0 nothing yet, < 0 an error) until it reports something or `spin`
// has passed, yielding the core between calls so that a peer sharing it runs. Returns the last result.
// `yield_first`: yield before the first call too, for a process that has just written what it now waits the
// answer to: the answer cannot be there yet, and the process that makes it may be waiting for this core.
template <class Poll>
int busy_poll(std::chrono::microseconds spin, Poll poll, bool yield_first = false) {
    const auto until = std::chrono::steady_clock::now() + spin;
    if (yield_first) sched_yield();
    for (;;) {
        const int n = poll();
        if (n != 0 || std::chrono::steady_clock::now() >= until) return n;
        sched_yield();
    }
}

}  // namespace hlacore
