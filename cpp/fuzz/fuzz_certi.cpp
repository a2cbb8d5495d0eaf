// libFuzzer target for hlacore-rtia's decoder of CERTI's federate protocol (cpp/certi/protocol.hpp): arbitrary
// bytes as a frame from a federate.
//
// The only exception allowed out of decode is ProtocolError. A frame that decodes encodes again, in its byte
// order, to a frame that decodes to the same message and encodes to the same bytes.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "certi/protocol.hpp"

using namespace hlacore::certi;

namespace {
void check(bool ok) {
    if (!ok) std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view frame(reinterpret_cast<const char*>(data), size);
    try {
        bool big = false;
        const Message m = decode(frame, &big);
        check(frame_length(frame) == size);
        const std::string again = encode(m, big);
        const Message back = decode(again);
        check(encode(back, big) == again);
        check(back.type == m.type && back.exception == m.exception && back.handles == m.handles && back.values == m.values);
    } catch (const ProtocolError&) {
    }
    return 0;
}
