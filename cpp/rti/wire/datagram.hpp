// Best-effort messages as UDP datagrams between a client and the gateway (docs/networking.md). A datagram is
// a header (magic, the connection's token, a sequence number; little-endian) followed by exactly one frame.
// The token, handed out in the Welcome over the (authenticated) stream, ties a datagram to its connection;
// the sequence numbers, one series per direction and connection, let the receiver count what was lost or
// came out of order.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "rti/wire/codec.hpp"

namespace hlacore::wire {

constexpr std::uint32_t kDatagramMagic = 0x44414c48;  // "HLAD"
constexpr std::size_t kDatagramHeaderBytes = 4 + 8 + 8;
// A whole datagram's default size limit: below a 1500-byte Ethernet MTU with the IP and UDP headers, so that
// no datagram is fragmented (a lost fragment loses the datagram). Larger best-effort messages go over TCP.
constexpr std::uint32_t kDefaultMaxDatagram = 1400;
// The largest payload a UDP datagram over IPv4 can carry.
constexpr std::uint32_t kMaxDatagramLimit = 65507;

struct DatagramHeader {
    std::uint64_t token = 0;
    std::uint64_t sequence = 0;
};

inline void put_datagram_header(std::string& out, std::uint64_t token, std::uint64_t sequence) {
    auto put = [&out](std::uint64_t v, int bytes) {
        for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
    };
    put(kDatagramMagic, 4);
    put(token, 8);
    put(sequence, 8);
}

// A datagram cut into its header and its one frame (a view into the datagram).
struct Datagram {
    DatagramHeader header;
    Frame frame;
};

// `datagram` read, or nothing when it is not an hlacore datagram holding exactly one whole frame: what a
// stray or forged datagram looks like, to be dropped without harm to anything.
inline std::optional<Datagram> read_datagram(std::string_view datagram) {
    if (datagram.size() < kDatagramHeaderBytes) return std::nullopt;
    auto get = [&datagram](std::size_t at, int bytes) {
        std::uint64_t v = 0;
        for (int i = 0; i < bytes; ++i) v |= static_cast<std::uint64_t>(static_cast<unsigned char>(datagram[at + i])) << (8 * i);
        return v;
    };
    if (get(0, 4) != kDatagramMagic) return std::nullopt;
    const std::string_view body = datagram.substr(kDatagramHeaderBytes);
    Datagram read{{get(4, 8), get(12, 8)}, {}};
    try {
        const std::size_t used = next_frame(body, read.frame, kMaxDatagramLimit);
        if (used == 0 || used != body.size()) return std::nullopt;
    } catch (const WireError&) {
        return std::nullopt;
    }
    return read;
}

// One end's counts: of the datagrams it sent, and of those it received from the other end.
struct DatagramStats {
    std::uint64_t sent = 0;        // datagrams handed to the socket
    std::uint64_t send_failed = 0;  // not taken by the socket (its buffer full): lost at the sender
    std::uint64_t oversize = 0;    // best-effort messages over the size limit, sent over the stream instead
    std::uint64_t received = 0;
    std::uint64_t lost = 0;        // sequence numbers never received (so far: a late one is taken back)
    std::uint64_t reordered = 0;   // received after a later one
    std::uint64_t duplicates = 0;  // received twice, or too late to tell: dropped
    std::uint64_t held_back = 0;   // received while flow control held the sender back: dropped (the gateway)
    std::uint64_t early = 0;       // a reflection ahead of its object's discovery: dropped (the client)
};

// The receiving end of one series of sequence numbers (from 1): counts each datagram, and says whether to
// deliver it (not a duplicate, and within the last 64 numbers).
class SequenceWindow {
public:
    bool accept(std::uint64_t sequence, DatagramStats& stats) {
        if (sequence > highest_) {
            const std::uint64_t gap = sequence - highest_;
            stats.lost += gap - 1;
            window_ = gap >= 64 ? 0 : window_ << gap;
            if (gap <= 64) window_ |= std::uint64_t{1} << (gap - 1);  // the previous highest
            highest_ = sequence;
            ++stats.received;
            return true;
        }
        const std::uint64_t behind = highest_ - sequence;  // 0: the highest itself
        if (sequence == 0 || behind == 0 || behind > 64 || (window_ & (std::uint64_t{1} << (behind - 1)))) {
            ++stats.duplicates;
            return false;
        }
        window_ |= std::uint64_t{1} << (behind - 1);
        --stats.lost;
        ++stats.reordered;
        ++stats.received;
        return true;
    }

private:
    std::uint64_t highest_ = 0;
    std::uint64_t window_ = 0;  // bit i set: highest_ - 1 - i was received
};

}  // namespace hlacore::wire
