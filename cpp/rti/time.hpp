// HLA 1.3 logical time as both sides of the connection see it: the time type, the advance kinds and the
// one rule they share, after(): the lowest timestamp a federate may send once its time is t.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

namespace hlacore {

using Time = double;
constexpr Time kInfinity = std::numeric_limits<double>::infinity();

enum class AdvanceKind : std::uint8_t {
    None = 0,
    TimeAdvanceRequest = 1,
    TimeAdvanceRequestAvailable = 2,
    NextEventRequest = 3,
    NextEventRequestAvailable = 4,
    FlushQueueRequest = 5,
};

inline bool is_available(AdvanceKind kind) {
    return kind == AdvanceKind::TimeAdvanceRequestAvailable || kind == AdvanceKind::NextEventRequestAvailable;
}

// after(t, L) of docs/time-management.md: t + L; with zero lookahead (or one lost in rounding) t itself when
// the federate may send at its own time (after an "available" request) and the next double above t otherwise
// (HLA 1.3 §8.1.1: no epsilon).
inline Time after(Time t, Time lookahead, bool strict) {
    if (lookahead > 0 && t + lookahead > t) return t + lookahead;
    return strict ? std::nextafter(t, kInfinity) : t;
}

}  // namespace hlacore
