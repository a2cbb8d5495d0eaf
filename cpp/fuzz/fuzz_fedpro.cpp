// libFuzzer target for the Federate Protocol's session layer (cpp/fedpro/session_protocol.hpp): arbitrary bytes
// as what a federate sends on a connection, cut into messages by their headers and run through the RTI's
// session state (numbering, what is kept, resumes).
//
// The only exception allowed out is BadMessage. The bytes kept are those of the kept messages; a message is
// taken at most once (a number not after the last taken is a repeat); a resume resends only kept messages.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fedpro/session_protocol.hpp"

using namespace hlacore::fedpro;

namespace {
void check(bool ok) {
    if (!ok) std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view in(reinterpret_cast<const char*>(data), size);
    SessionState state(42);
    try {
        while (in.size() >= kHeaderSize) {
            const Header h = decode_header(in, 1u << 16);
            check(h.size >= kHeaderSize && h.size <= (1u << 16));
            if (in.size() < h.size) break;
            const std::string_view payload = in.substr(kHeaderSize, h.size - kHeaderSize);
            in.remove_prefix(h.size);
            if (h.type == MessageType::NewSession || h.type == MessageType::ResumeRequest) {
                const SessionState::Resume r = state.resume(payload_u32(payload, 0));
                check(r.status != kResumeOk || r.resend.size() == state.kept_messages());
                for (auto const& bytes : r.resend) check(decode_header(bytes, 1u << 20).type == MessageType::HlaCallbackRequest);
                continue;
            }
            const std::uint32_t before = state.last_received();
            if (state.receive(h)) {
                check(after(h.sequence, before) && state.last_received() == h.sequence);
                // Each message the federate sends gets one of ours back, kept until the federate confirms it.
                const std::string bytes = state.frame(MessageType::HlaCallbackRequest, payload);
                check(decode_header(bytes, 1u << 20).size == bytes.size());
            } else {
                check(state.last_received() == before);
            }
            if (state.kept_messages() == 0) check(state.kept_bytes() == 0);
        }
    } catch (const BadMessage&) {
    }
    return 0;
}
