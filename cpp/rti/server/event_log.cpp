#include "rti/server/event_log.hpp"

#include <chrono>

#include "rti/wire/json.hpp"

namespace hlacore {

namespace {

// Names come from clients and may be as long as a frame: an event keeps their first kMaxText bytes, cut
// before a UTF-8 continuation byte so that the text stays valid, and marked as cut.
constexpr std::size_t kMaxText = 256;

std::string clipped(const std::string& text) {
    if (text.size() <= kMaxText) return text;
    std::size_t end = kMaxText;
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
    return text.substr(0, end) + "\u2026";  // an ellipsis
}

}  // namespace

void EventLog::add(const char* kind, const std::string& federation, std::uint32_t federate, const std::string& name,
                   const std::string& reason) {
    const double now = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
    events_.push_back(Event{++last_, now, kind, clipped(federation), clipped(name), clipped(reason), federate});
    if (events_.size() > kKept) events_.pop_front();
}

void EventLog::write_after(std::uint64_t after, std::string& out) const {
    out += ",\"events\":[";
    bool first = true;
    for (const Event& e : events_) {
        if (e.sequence <= after) continue;
        if (!first) out += ',';
        first = false;
        out += "{\"sequence\":" + std::to_string(e.sequence) + ",\"time\":";
        json_number(out, e.wall_time);
        out += ",\"kind\":\"" + std::string(e.kind) + "\",\"federation\":";
        json_text(out, e.federation);
        out += ",\"federate\":" + std::to_string(e.federate) + ",\"name\":";
        json_text(out, e.name);
        out += ",\"reason\":";
        json_text(out, e.reason);
        out += '}';
    }
    out += "],\"last_event\":" + std::to_string(last_);
}

}  // namespace hlacore
