// Large values written from where they are instead of being copied into an output buffer: a federate's
// send (client/writer.cpp) writes them from the caller's bytes, the gateway (server/connection.hpp) from the
// sender's read block. The buffer holds the rest of the stream; each splice goes in at its offset.
#pragma once

#include <sys/uio.h>

#include <cstddef>
#include <string>
#include <string_view>

#include "rti/wire/codec.hpp"

namespace hlacore::wire {

// `bytes` go into the stream at offset `at` of the buffer (before what the buffer holds from there on).
struct Splice {
    std::size_t at;
    std::string_view bytes;
};

// An output for encode_to(): appends to `out`, except each value of kSplicedValueBytes or more that
// `splice(at, bytes)` takes (returns true for): the callback notes where it goes instead.
template <class SpliceValue>
struct SplicingOutput {
    std::string& out;
    SpliceValue splice;
    void append(const char* p, std::size_t n) {
        if (n >= kSplicedValueBytes && splice(out.size(), std::string_view(p, n))) return;
        out.append(p, n);
    }
    void append(const std::string& s) { out.append(s); }
};
template <class SpliceValue>
SplicingOutput(std::string&, SpliceValue) -> SplicingOutput<SpliceValue>;

// The iovecs of `buffer` from `from` on with `splices` (in order, each `at` >= from) between, in stream order,
// into `pieces` (room for `max`, at least 1; 2 per splice + 1 takes all). When they do not all fit, it ends
// at the start of a splice. Returns how many; empty pieces are left out.
template <class Splices>
std::size_t gather(std::string_view buffer, std::size_t from, const Splices& splices, iovec* pieces, std::size_t max) {
    std::size_t n = 0;
    const auto piece = [&](const char* p, std::size_t size) {
        if (size > 0) pieces[n++] = iovec{const_cast<char*>(p), size};
    };
    for (const auto& s : splices) {
        piece(buffer.data() + from, s.at - from);
        if (n + 2 > max) return n;  // no room for the splice and what comes after it
        piece(s.bytes.data(), s.bytes.size());
        from = s.at;
    }
    piece(buffer.data() + from, buffer.size() - from);
    return n;
}

}  // namespace hlacore::wire
