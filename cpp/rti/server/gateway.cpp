// The gateway's path of a request: what a connection reads is cut into frames, decoded and dispatched once
// (on_request) onto the serve() overload of its type. The reactor around it is reactor.cpp, the stream
// I/O transport.cpp, the handshake session.cpp, flow control flow_control.cpp, and the federation
// management it serves itself federations.cpp.
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
            on_frame(c, frame);
            if (!connections_.count(fd)) return;
            if (!c.in.empty()) c.partial_since = Clock::now();
            pause_if_over_budget(c);
            if (!connections_.count(fd)) return;
        }
    } catch (const wire::WireError& e) {
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
template <class View>
void Gateway::serve_view(Connection& c, const wire::Frame& frame) {
    check_forwardable(frame, options_.max_frame_bytes);
    const View view = wire::decode_as<View>(frame);
    if (recorder_ && c.federation) recorder_->request(c.federation->federation, c.federate, view);
    if (frame.payload.size() < wire::kSplicedValueBytes) return serve(c, view);
    struct Scope {  // the block is let go once served, whatever happens
        SpliceSource& source;
        ~Scope() { source = {}; }
    } scope{splice_source_};
    splice_source_ = {c.in.share(), frame.payload};
    serve(c, view);
}

void Gateway::on_frame(Connection& c, const wire::Frame& frame) {
    // Updates and interactions, when nothing needs them whole (the trace): served with their values viewed in
    // the frame rather than copied out of it, a camera frame's megabytes included.
    if (c.greeted && c.challenge.empty() && !trace_) {
        if (frame.type == wire::MessageType::UpdateAttributes) return serve_view<wire::UpdateAttributesView>(c, frame);
        if (frame.type == wire::MessageType::SendInteraction) return serve_view<wire::SendInteractionView>(c, frame);
    }
    wire::Message message = wire::decode(frame);
    if (!c.greeted || !c.challenge.empty()) return greet(c, frame.type, message);  // session.cpp
    check_forwardable(frame, options_.max_frame_bytes);
    if (trace_ && c.federation) trace_->received(c.federation->federation.name(), c.federate, message, c.read_ns);
    on_request(c, message);
}

// The one dispatcher of the gateway process: each message goes to the overload of serve() for its type.
// Requests with a result are served here; everything else a joined federate sends goes to its federation.
void Gateway::on_request(Connection& c, const wire::Message& message) {
    if (recorder_ && c.federation) recorder_->request(c.federation->federation, c.federate, message);
    std::visit([&](const auto& m) { serve(c, m); }, message);
}

Federation& Gateway::joined(const Connection& c) const {
    if (!c.federation) throw RtiError(ErrorCode::FederateNotExecutionMember, "not joined to a federation");
    return c.federation->federation;
}

const std::string& Gateway::federation_name(const Connection& c) const { return c.federation->federation.name(); }

namespace {
template <class M>
const char* name_of() {
    if constexpr (std::is_same_v<M, std::monostate>) {
        return wire::message_name(wire::MessageType::Invalid);
    } else {
        return wire::message_name(M::kType);
    }
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

}  // namespace hlacore
