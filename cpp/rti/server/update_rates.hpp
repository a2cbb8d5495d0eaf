// IEEE 1516-2010's update rate reduction at the gateway, for one subscribing federate: a class subscribed
// with an update rate (SubscriptionRate, the FOM's rate in updates a second) gets each receive-order
// attribute of an object at most that often, by the wall clock; the values in between are not sent to it
// (what a display drawing at 10 Hz asks of a 1 kHz publisher). Timestamped values are never dropped: time
// management counts on every one. Attached to a federate once it names a rate, so the routing of updates
// tests one pointer for everyone else.
#pragma once

#include <chrono>
#include <map>
#include <utility>

#include "fed_parser/fom.hpp"

namespace hlacore {

class UpdateRateLimits {
public:
    using Clock = std::chrono::steady_clock;

    // `rate` a second for the class's subscribed attributes; 0: no limit.
    void set(fom::Handle object_class, double rate);
    // Whether a receive-order value of `attribute` of `object`, known as `object_class`, goes out now (noted
    // as sent when it does); the clock is read only for a class with a rate.
    bool due(fom::Handle object_class, std::uint32_t object, fom::Handle attribute);
    // An object the federate no longer knows: its times go.
    void forget(std::uint32_t object);

private:
    std::map<fom::Handle, Clock::duration> interval_;                           // class -> least time between values
    std::map<std::pair<std::uint32_t, fom::Handle>, Clock::time_point> sent_;  // (object, attribute) -> last sent
};

}  // namespace hlacore
