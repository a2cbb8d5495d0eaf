// Blocking waits of the client, shared by its files: the time left for poll(), and the WaitHost's
// begin_wait/end_wait around a wait (the GIL released, for Python).
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>

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

}  // namespace hlacore
