// Blocking waits on a connection's socket, for the federate side and rtig --status alike: the program around
// a call (WaitHost: the Python binding releases the GIL and turns Ctrl-C into KeyboardInterrupt), the time
// left for poll(), and one bounded wait that hands signals to the host.
#pragma once

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

#include <poll.h>

namespace hlacore {

// What the program around a client does while one of its calls blocks. The Python binding releases the
// GIL and turns Ctrl-C into KeyboardInterrupt; without a host, waits go on through signals.
class WaitHost {
public:
    virtual ~WaitHost() = default;
    // Around a wait that may block; begin's result is given back to end.
    virtual void* begin_wait() { return nullptr; }
    virtual void end_wait(void*) {}
    // A signal interrupted the wait: throw to abandon it, return to go on waiting.
    virtual void interrupted() {}
};

// A duration for a message: "2.5 s".
inline std::string seconds(std::chrono::steady_clock::duration d) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f s", std::chrono::duration<double>(d).count());
    return text;
}

// Milliseconds left until `deadline` for poll(), at least 0.
inline int ms_until(std::chrono::steady_clock::time_point deadline) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    return static_cast<int>(std::clamp<std::int64_t>(left.count() + 1, 0, 1 << 30));
}

// The host's begin_wait/end_wait around one blocking wait.
class Waiting {
public:
    explicit Waiting(WaitHost* host) : host_(host), token_(host ? host->begin_wait() : nullptr) {}
    ~Waiting() {
        if (host_) host_->end_wait(token_);
    }
    Waiting(const Waiting&) = delete;
    Waiting& operator=(const Waiting&) = delete;

private:
    WaitHost* host_;
    void* token_;
};

// Waits until `fd` has one of `events` or `deadline` passes, the GIL released; a signal goes to the host
// (which may throw, for Ctrl-C) and the wait goes on. Returns poll()'s count: 1 ready, 0 timed out, -1 failed.
inline int poll_until(WaitHost* host, int fd, short events, std::chrono::steady_clock::time_point deadline) {
    for (;;) {
        pollfd p{fd, events, 0};
        int n;
        {
            Waiting waiting(host);
            n = ::poll(&p, 1, ms_until(deadline));
        }
        if (n >= 0 || errno != EINTR) return n;
        if (host) host->interrupted();
    }
}

}  // namespace hlacore
