// The gateway's path of a request: what a connection reads is cut into frames, each decoded and dispatched
// once (on_request) onto the serve() overload of its type, past the taps. Around it: the reactor (reactor.cpp),
// the stream I/O (transport.cpp), the handshake (session.cpp), flow control (flow_control.cpp) and the
// federation management the gateway serves itself (federations.cpp).
#include "rti/server/gateway.hpp"
#include "rti/server/gateway_internal.hpp"

#include <new>
#include <string>

namespace hlacore {

namespace {
// Bounded per turn so that one busy peer cannot starve the others.
constexpr std::size_t kReadBudget = 16 * wire::ReadBuffer::kChunk;
}  // namespace

void Gateway::on_readable(Connection& c) {
    const int fd = c.fd;
    bool peer_closed = false;
    std::string error;
    try {
        error = c.ssl ? read_tls(c, kReadBudget, peer_closed) : read_plain(c, kReadBudget, peer_closed);
    } catch (const std::bad_alloc&) {  // the block a large frame reserves once its header is in
        error = "no memory for a frame of " + std::to_string(c.in.unread().size() + c.in.wanted(options_.max_frame_bytes)) +
                " bytes";
    }
    if (trace_) c.read_ns = MessageTrace::now_ns();
    if (!error.empty()) {
        // What a greeted client sent before the error is served first: a federate killed with messages
        // unread resets its connection, and the frames read just before the reset were its last words.
        if (c.greeted) serve_frames(c);
        if (connections_.count(fd)) close(fd, error);
        return;
    }
    serve_frames(c);
    if (!connections_.count(fd)) return;
    if (peer_closed) {
        const std::size_t left = c.in.unread().size();
        close(fd, left ? "connection closed in the middle of a frame (" + std::to_string(left) + " bytes pending)"
                       : "connection closed by peer");
    }
}

void Gateway::serve_frames(Connection& c) {
    const int fd = c.fd;
    try {
        wire::Frame frame;
        while (!c.paused) {
            const std::size_t used = wire::next_frame(c.in.unread(), frame, options_.max_frame_bytes);
            if (!used) break;
            // The frame stays where it is until the next read: consumed now, served from there.
            c.in.consume(used);
            if (used > kKeptBufferBytes) {
                large_frame_at_ = Clock::now();
                large_buffers_kept_ = true;
            }
            over_budget_ = -1;
            serving_ = fd;
            on_frame(c, frame);
            serving_ = -1;
            if (!connections_.count(fd)) return;
            if (!c.in.empty()) c.partial_since = Clock::now();
            pause_if_over_budget(c);
            if (!connections_.count(fd)) return;
        }
    } catch (const wire::WireError& e) {
        serving_ = -1;
        close(fd, std::string("protocol error: ") + e.what());
        return;
    }
    if (!keeping_large_buffers()) c.in.release_above(kKeptBufferBytes);
}

namespace {
// Clients refuse these at the call (ValueLengthExceeded): forwarded, they would not fit.
void check_forwardable(const wire::Frame& frame, std::uint32_t max_frame_bytes) {
    switch (frame.type) {
        case wire::MessageType::UpdateAttributes:
        case wire::MessageType::SendInteraction:
        case wire::MessageType::SendInteractionWithRegion:
            if (2 + frame.payload.size() + wire::kForwardedGrowth > max_frame_bytes)
                throw wire::WireError(std::string(wire::message_name(frame.type)) + " of " +
                                      std::to_string(2 + frame.payload.size()) +
                                      " bytes would be forwarded over the frame limit of " +
                                      std::to_string(max_frame_bytes) + " bytes");
            break;
        default: break;
    }
}
}  // namespace
void Gateway::on_frame(Connection& c, const wire::Frame& frame) {
    if (!c.greeted || !c.challenge.empty()) return greet(c, frame.type, wire::decode(frame));  // session.cpp
    check_forwardable(frame, options_.max_frame_bytes);
    if (frame.payload.size() < wire::kSplicedValueBytes) return on_request(c, frame);
    // A large update's or interaction's values go to the receivers from the block they were read into
    // (ConnectionOutbox::spliced): the block is shared while the frame is served, and let go after.
    struct Scope {
        SpliceSource& source;
        ~Scope() { source = {}; }
    } scope{splice_source_};
    splice_source_ = {c.in.share(), frame.payload};
    on_request(c, frame);
}

namespace {
// The form the gateway serves each message in: updates and interactions with their values viewed in the frame
// rather than copied out of it (a camera frame is megabytes), everything else as it is.
template <class M>
struct Served {
    using type = M;
};
template <>
struct Served<wire::UpdateAttributes> {
    using type = wire::UpdateAttributesView;
};
template <>
struct Served<wire::SendInteraction> {
    using type = wire::SendInteractionView;
};
}  // namespace

// The one dispatcher of the gateway process: a switch over the frame's type decodes the message in the form it
// is served in and serves it (serve_message). The datagrams, only updates and interactions, decode theirs as
// they check them (datagrams.cpp) and go straight to serve_message. Requests with a result are served by the gateway; everything else a joined federate
// sends goes to its federation.
void Gateway::on_request(Connection& c, const wire::Frame& frame) {
    switch (frame.type) {
#define HLACORE_X(name)             \
    case wire::MessageType::name:   \
        return serve_frame<Served<wire::name>::type>(c, frame);
        HLACORE_MESSAGES(HLACORE_X)
#undef HLACORE_X
        default: throw wire::WireError("unknown message type " + std::to_string(static_cast<unsigned>(frame.type)));
    }
}

template <class M>
void Gateway::serve_frame(Connection& c, const wire::Frame& frame) {
    serve_message(c, wire::decode_as<M>(frame));
}

// Shows the message to the taps and hands it to the overload of serve() for its type.
template <class M>
void Gateway::serve_message(Connection& c, const M& m) {
    if ((recorder_ || trace_) && c.federation) tap(c, m);
    if constexpr (std::is_same_v<M, wire::DeleteObject>) memory_freed_ = true;
    serve(c, m);
}

// The taps: the recording (rtig --record, or a recorder federate) and the message trace (rtig --trace), each
// attached when asked for; a request meets them here and nowhere else.
template <class M>
void Gateway::tap(Connection& c, const M& m) {
    if (recorder_) recorder_->request(c.federation->federation, c.federate, m);
    if (trace_) trace_->received(c.federation->federation.name(), c.federate, m, c.read_ns);
}

Federation& Gateway::joined(const Connection& c) const {
    if (!c.federation) throw RtiError(ErrorCode::FederateNotExecutionMember, "not joined to a federation");
    return c.federation->federation;
}

const std::string& Gateway::federation_name(const Connection& c) const { return c.federation->federation.name(); }

namespace {
template <class M>
const char* name_of() {
    return wire::message_name(M::kType);
}
}  // namespace
template <class M>
void Gateway::serve(Connection& c, const M& m) {
    if (!c.federation) throw wire::WireError(std::string(name_of<M>()) + " sent before joining a federation");
    try {
        c.federation->federation.handle(c.federate, m);
    } catch (const RtiError& e) {
        throw wire::WireError(std::string("refused ") + name_of<M>() + ": " + e.what());
    }
}

// The two the datagrams serve (datagrams.cpp).
template void Gateway::serve_message(Connection&, const wire::UpdateAttributesView&);
template void Gateway::serve_message(Connection&, const wire::SendInteractionView&);

}  // namespace hlacore
