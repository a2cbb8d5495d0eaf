// The gateway's recent membership history for the status report: federations created and destroyed,
// federates joined, resigned and dropped (with the reason). Bounded: the last kKept events, each name and
// reason cut to 256 bytes; a reader asks for those after the last sequence number it saw, so a monitor
// polling every half second costs a few bytes.
#pragma once

#include <cstdint>
#include <deque>
#include <string>

namespace hlacore {

class EventLog {
public:
    static constexpr std::size_t kKept = 256;

    // `kind`: "created", "destroyed", "joined", "resigned" or "dropped"; `federate` 0 for a federation's events.
    void add(const char* kind, const std::string& federation, std::uint32_t federate, const std::string& name,
             const std::string& reason = {});
    // Appends ,"events":[...] (those numbered above `after`, oldest first) and ,"last_event":N.
    void write_after(std::uint64_t after, std::string& json) const;

private:
    struct Event {
        std::uint64_t sequence;
        double wall_time;  // seconds since the Unix epoch
        const char* kind;
        std::string federation, name, reason;
        std::uint32_t federate;
    };
    std::deque<Event> events_;
    std::uint64_t last_ = 0;
};

}  // namespace hlacore
