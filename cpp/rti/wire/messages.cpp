// The runtime half of the wire protocol (messages.hpp): message names and framing, which know the messages
// only by their codes.
#include "rti/wire/codec.hpp"

namespace hlacore::wire {

const char* message_name(MessageType type) {
    static constexpr const char* kNames[] = HLACORE_LIST_NAMES(HLACORE_MESSAGES);
    return list_name(kNames, static_cast<std::size_t>(type), "unknown");
}

void Reader::fail(const char* what) const {
    throw WireError(std::string(what) + " in " + message_name(type_) + " message");
}

void encode(std::string& out, const Message& m) {
    std::visit(
        [&out](const auto& msg) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(msg)>, std::monostate>) encode(out, msg);
        },
        m);
}

std::size_t next_frame(std::string_view buffer, Frame& frame, std::uint32_t max_bytes) {
    if (buffer.size() < kHeaderBytes) return 0;
    std::uint32_t length = 0;
    std::uint16_t type = 0;
    std::memcpy(&length, buffer.data(), 4);
    std::memcpy(&type, buffer.data() + 4, 2);
    if (length < 2) throw WireError("frame length " + std::to_string(length) + " is shorter than its type field");
    if (length > max_bytes)
        throw WireError("frame length " + std::to_string(length) + " exceeds the limit of " + std::to_string(max_bytes) +
                        " bytes");
    if (buffer.size() < 4 + static_cast<std::size_t>(length)) return 0;
    frame.type = static_cast<MessageType>(type);
    frame.payload = buffer.substr(kHeaderBytes, length - 2);
    return 4 + static_cast<std::size_t>(length);
}

}  // namespace hlacore::wire
