#include "fedpro/session_protocol.hpp"

namespace hlacore::fedpro {

namespace {

std::uint32_t get32(std::string_view b, std::size_t at) {
    const auto* p = reinterpret_cast<const unsigned char*>(b.data() + at);
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

void put32(std::string& out, std::uint32_t v) {
    const char b[4] = {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
    out.append(b, 4);
}

bool known(std::uint32_t type) {
    return (type >= 1 && type <= 6) || type == 10 || type == 11 || (type >= 20 && type <= 23);
}

bool is_hla(MessageType type) { return static_cast<std::uint32_t>(type) >= 20; }

}  // namespace

const char* name(MessageType type) {
    switch (type) {
        case MessageType::NewSession: return "NewSession";
        case MessageType::NewSessionStatus: return "NewSessionStatus";
        case MessageType::Heartbeat: return "Heartbeat";
        case MessageType::HeartbeatResponse: return "HeartbeatResponse";
        case MessageType::TerminateSession: return "TerminateSession";
        case MessageType::SessionTerminated: return "SessionTerminated";
        case MessageType::ResumeRequest: return "ResumeRequest";
        case MessageType::ResumeStatus: return "ResumeStatus";
        case MessageType::HlaCallRequest: return "HlaCallRequest";
        case MessageType::HlaCallResponse: return "HlaCallResponse";
        case MessageType::HlaCallbackRequest: return "HlaCallbackRequest";
        case MessageType::HlaCallbackResponse: return "HlaCallbackResponse";
    }
    return "unknown";
}

Header decode_header(std::string_view bytes, std::uint32_t max_size) {
    if (bytes.size() < kHeaderSize) throw BadMessage("a header is 24 bytes, not " + std::to_string(bytes.size()));
    Header h;
    h.size = get32(bytes, 0);
    if (h.size < kHeaderSize) throw BadMessage("a message of " + std::to_string(h.size) + " bytes, under its header's 24");
    if (h.size > max_size)
        throw BadMessage("a message of " + std::to_string(h.size) + " bytes, over the limit of " + std::to_string(max_size));
    h.sequence = get32(bytes, 4);
    h.session = std::uint64_t(get32(bytes, 8)) << 32 | get32(bytes, 12);
    h.last_received = get32(bytes, 16);
    const std::uint32_t type = get32(bytes, 20);
    if (!known(type)) throw BadMessage("unknown message type " + std::to_string(type));
    h.type = static_cast<MessageType>(type);
    return h;
}

std::string encode_header(Header const& h) {
    std::string out;
    out.reserve(kHeaderSize);
    put32(out, h.size);
    put32(out, h.sequence);
    put32(out, std::uint32_t(h.session >> 32));
    put32(out, std::uint32_t(h.session));
    put32(out, h.last_received);
    put32(out, static_cast<std::uint32_t>(h.type));
    return out;
}

std::uint32_t payload_u32(std::string_view payload, std::size_t index) {
    if (payload.size() < 4 * (index + 1))
        throw BadMessage("a payload of " + std::to_string(payload.size()) + " bytes, too short for its numbers");
    return get32(payload, 4 * index);
}

std::string u32s(std::initializer_list<std::uint32_t> values) {
    std::string out;
    for (auto v : values) put32(out, v);
    return out;
}

bool after(std::uint32_t a, std::uint32_t b) {
    const std::uint32_t d = (a - b) & kSequenceMask;
    return d != 0 && d < 0x40000000u;
}

std::string SessionState::frame(MessageType type, std::string_view payload) {
    const std::uint32_t n = next_;
    next_ = next(next_);
    std::string bytes = encode_header({std::uint32_t(kHeaderSize + payload.size()), n, id_, last_received_, type});
    bytes.append(payload);
    if (is_hla(type)) {
        kept_bytes_ += bytes.size();
        kept_.push_back({n, bytes});
    }
    return bytes;
}

std::string SessionState::first_frame(MessageType type, std::string_view payload) const {
    std::string bytes = encode_header({std::uint32_t(kHeaderSize + payload.size()), 0, id_, last_received_, type});
    bytes.append(payload);
    return bytes;
}

bool SessionState::receive(Header const& h) {
    if (h.session != id_) throw BadMessage("a message of session " + std::to_string(h.session) + " in session " + std::to_string(id_));
    if (!valid_sequence(h.sequence)) throw BadMessage("sequence number " + std::to_string(h.sequence) + " out of range");
    if (valid_sequence(h.last_received)) release_through(h.last_received);
    if (!after(h.sequence, last_received_)) return false;
    last_received_ = h.sequence;
    if (is_hla(h.type)) last_hla_received_ = h.sequence;
    return true;
}

void SessionState::release_through(std::uint32_t n) {
    if (!after(n, confirmed_)) return;
    confirmed_ = n;
    while (!kept_.empty() && !after(kept_.front().sequence, n)) {
        kept_bytes_ -= kept_.front().bytes.size();
        kept_.pop_front();
    }
}

SessionState::Resume SessionState::resume(std::uint32_t last_received_by_federate) {
    Resume r;
    // The federate cannot have lost what it said it had. (The oldest message it still keeps, which it sends too,
    // is not checked against what we lack: the numbers between may be control messages, which nobody keeps.)
    if (!valid_sequence(last_received_by_federate) || after(confirmed_, last_received_by_federate)) {
        r.status = kNotEnoughBuffered;
        return r;
    }
    release_through(last_received_by_federate);
    for (auto& k : kept_) {
        std::string bytes = k.bytes;
        const std::string stamp = u32s({last_received_});
        bytes.replace(16, 4, stamp);
        r.resend.push_back(std::move(bytes));
    }
    return r;
}

}  // namespace hlacore::fedpro
