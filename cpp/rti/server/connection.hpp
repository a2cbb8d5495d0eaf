// A client's connection to the gateway: its buffers, flow-control state and datagram path, in one place for
// the gateway's files (gateway_internal.hpp names them).
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <deque>
#include <iterator>
#include <memory>
#include <string>
#include <string_view>

#include <sys/socket.h>
#include <sys/uio.h>

#include "rti/server/gateway.hpp"
#include "rti/wire/datagram.hpp"
#include "rti/wire/read_buffer.hpp"
#include "rti/wire/splices.hpp"

namespace hlacore {

struct Gateway::Connection {
    using Clock = std::chrono::steady_clock;

    int fd = -1;
    std::string peer;
    bool local = false;  // over the Unix socket (GatewayOptions::unix_path): no TLS, no datagrams
    // With TLS (rtig --tls-cert): the session, in accept state, on the non-blocking socket. A read that must
    // write first (the handshake's answer to a full socket) waits for EPOLLOUT, a write that must read first
    // for EPOLLIN.
    tls::Session ssl;
    bool read_wants_write = false;
    bool write_wants_read = false;
    wire::ReadBuffer in;
    std::string out;
    std::size_t out_offset = 0;
    // Large values of forwarded updates and interactions, written from the sender's read block (kept alive
    // here) rather than copied into `out`: each goes into the stream at offset `at` of `out`, in order, and
    // `bytes` is what is left to write of it.
    struct Splice : wire::Splice {
        std::shared_ptr<const char[]> block;
    };
    std::deque<Splice> splices;
    std::size_t splice_bytes = 0;
    // Released held messages waiting to enter `out` as the client takes what is there (at most kPacedBytes
    // at a time), then `tail`: what was written for the client meanwhile, kept behind them.
    std::deque<std::string> backlog;
    std::size_t backlog_bytes = 0;
    // Spilling (server/spill.hpp): while the client is over its budget in memory, what is written for it goes
    // through `tail` to this file, between the backlog and `tail` in the stream; `spill_failed` says why the
    // connection is dropped at the end of the turn when spilling failed.
    std::unique_ptr<SpillFile> spill;
    std::unique_ptr<SpillFile> parked;  // the messages time management holds for it, beyond its share (FrameParking)
    std::string spill_failed;
    std::string tail;
    bool greeted = false;
    std::string challenge;  // sent in the Welcome while the gateway has a secret and the client has not answered
    std::string nonce;      // sent in the Welcome when some federation has a secret: its proofs sign it
    bool write_armed = false;
    bool dirty = false;
    FederationEntry* federation = nullptr;
    std::unique_ptr<RecordTap> tap;  // a recorder federate's: its federation's records (server/recorder.hpp)
    FederateHandle federate = 0;
    Clock::time_point partial_since{};
    Clock::time_point accepted_at = Clock::now();
    // Flow control: while paused the connection is not read (its frames wait in its socket) until the
    // client it sends to (blocked_by, a descriptor) is below half its budget again.
    bool paused = false;
    int blocked_by = -1;
    Clock::time_point paused_since{};
    Clock::time_point keepalive_at{};
    bool pause_logged = false;
    bool idle = true;                // the output queue was empty at the end of the last flush
    Clock::time_point progress_at{};  // since then: when the client last took bytes, or bytes were queued
    std::int64_t read_ns = 0;  // when the bytes being decoded were read (message trace only)
    std::size_t traced = 0;    // out[0, traced) went through the message trace
    // Best effort over UDP (server/datagrams.cpp): the token of this connection's datagrams, where they come
    // from (the address its DatagramHello came from), whether the client takes datagrams (its DatagramPath),
    // the last sequence number sent to it, what came from it, and the counts.
    std::uint64_t datagram_token = 0;
    sockaddr_storage datagram_peer{};
    socklen_t datagram_peer_length = 0;
    bool datagram_path = false;
    std::uint64_t datagram_sequence = 0;
    wire::SequenceWindow datagram_window;
    wire::DatagramStats datagrams;

    // What is written for the client and not taken yet: `out` from out_offset on, and the splices.
    std::size_t unsent() const { return out.size() - out_offset + splice_bytes; }
    // `n` more bytes were taken, in stream order.
    void sent(std::size_t n) {
        while (n > 0) {
            const std::size_t before = (splices.empty() ? out.size() : splices.front().at) - out_offset;
            if (before > 0) {
                const std::size_t k = std::min(n, before);
                out_offset += k;
                n -= k;
                continue;
            }
            if (splices.empty()) return;
            Splice& s = splices.front();
            const std::size_t k = std::min(n, s.bytes.size());
            s.bytes.remove_prefix(k);
            splice_bytes -= k;
            n -= k;
            if (s.bytes.empty()) splices.pop_front();
        }
    }
    // One sendmsg (MSG_NOSIGNAL) of what is queued, in stream order: `out` around the splices and their values.
    ssize_t write_queued() const {
        iovec pieces[32];
        msghdr message{};
        message.msg_iov = pieces;
        message.msg_iovlen = wire::gather(out, out_offset, splices, pieces, std::size(pieces));
        return ::sendmsg(fd, &message, MSG_NOSIGNAL);
    }
    // Writes the spliced values into `out` where they go, letting go of the senders' read blocks they pin: a
    // client that stopped reading must not keep its senders from being read (its stream goes to a spill file).
    void inline_splices() {
        if (splices.empty()) return;
        std::string flat;
        flat.reserve(unsent());
        std::size_t from = out_offset;
        for (const Splice& s : splices) {
            flat.append(out, from, s.at - from);
            flat.append(s.bytes);
            from = s.at;
        }
        flat.append(out, from, std::string::npos);
        out = std::move(flat);
        out_offset = 0;
        traced = 0;  // nothing is spliced while the trace runs
        splices.clear();
        splice_bytes = 0;
    }
    // Drops out[0, out_offset), which was taken.
    void drop_sent() {
        out.erase(0, out_offset);
        for (Splice& s : splices) s.at -= out_offset;
        out_offset = 0;
    }
};

}  // namespace hlacore
