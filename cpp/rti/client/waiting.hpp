// Blocking waits of the client, shared by its files: the time left for poll(), and the WaitHost's
// begin_wait/end_wait around a wait (the GIL released, for Python).
#pragma once

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cstdint>

#include <poll.h>

#include "rti/client/client.hpp"

namespace hlacore {

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
