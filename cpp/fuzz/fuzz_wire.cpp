// libFuzzer target for the wire codec: arbitrary bytes as they would arrive on a gateway socket.
//
// The input is cut into frames with next_frame() exactly as the gateway's read loop does, and every frame
// is decoded. Beyond "no crash, no sanitizer report, no exception but WireError", each frame that decodes
// must encode back to the very same bytes (the encoding is canonical: booleans are 0/1, an absent time
// has no double, counts are exact), so the decoder cannot silently accept and misread anything.
//
// With HLACORE_FUZZ_EXPECT_VALID=1 in the environment, a complete frame that does not decode aborts: the
// test suite replays the seed corpus that way to show the seeds are valid frames (reaching the re-encoding).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "rti/wire/codec.hpp"

using namespace hlacore::wire;

namespace {
const bool expect_valid = [] {
    const char* v = std::getenv("HLACORE_FUZZ_EXPECT_VALID");
    return v != nullptr && std::string_view(v) == "1";
}();

[[noreturn]] void mismatch(const Frame& frame, std::string_view original, const std::string& again) {
    std::fprintf(stderr, "fuzz_wire: %s frame of %zu bytes re-encodes to %zu different bytes\n",
                 message_name(frame.type), original.size(), again.size());
    std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view buffer(reinterpret_cast<const char*>(data), size);
    // Bounded: every accepted frame consumes at least kHeaderBytes.
    while (!buffer.empty()) {
        Frame frame;
        std::size_t used = 0;
        try {
            used = next_frame(buffer, frame);
        } catch (const WireError& e) {
            if (expect_valid) {
                std::fprintf(stderr, "fuzz_wire: invalid header: %s\n", e.what());
                std::abort();
            }
            return 0;  // an impossible header: the gateway drops the peer
        }
        if (used == 0) return 0;  // incomplete: the gateway waits for more bytes
        if (used < kHeaderBytes || used > buffer.size()) std::abort();
        if (frame.payload.size() != used - kHeaderBytes) std::abort();
        if (frame.payload.data() != buffer.data() + kHeaderBytes) std::abort();
        try {
            const Message m = decode(frame);
            if (m.index() != static_cast<std::size_t>(frame.type)) std::abort();
            std::string again;
            encode(again, m);
            if (again != buffer.substr(0, used)) mismatch(frame, buffer.substr(0, used), again);
        } catch (const WireError& e) {
            if (expect_valid) {
                std::fprintf(stderr, "fuzz_wire: invalid frame: %s\n", e.what());
                std::abort();
            }
            // a malformed payload: the gateway drops the peer; go on with the next frame to cover more
        }
        buffer.remove_prefix(used);
    }
    return 0;
}
