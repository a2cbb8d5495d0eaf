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

// Which reading of HLA 1.3's time rules a federation follows (docs/time-management.md). Exact: a federate
// enabling regulation starts above what every constrained federate may no longer receive (just above a TAR
// grant's time with zero lookahead). Certi: at the constrained federates' time, as CERTI does, so that a
// federate joining a zero-lookahead TAR(now) loop is granted with it. Default (on the wire only): the
// gateway's --time-semantics.
enum class TimeSemantics : std::uint8_t { Default = 0, Exact = 1, Certi = 2 };

inline const char* name_of(TimeSemantics s) {
    return s == TimeSemantics::Certi ? "certi" : s == TimeSemantics::Exact ? "exact" : "default";
}

// A federation's logical time type (IEEE 1516-2010 §12.1's two standard ones): the time travels as a double
// either way, an integer time being a whole number of units; HLA 1.3 federates see it as a double.
enum class TimeType : std::uint8_t { Float64 = 0, Integer64 = 1 };

inline const char* name_of(TimeType t) { return t == TimeType::Integer64 ? "HLAinteger64Time" : "HLAfloat64Time"; }

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
