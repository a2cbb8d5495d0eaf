#include "fedpro/session.hpp"

#include <cstdio>

#include "rti/wire/json.hpp"

namespace hlacore::fedpro {

namespace {
// A federate that takes nothing for this long while we write to it is gone: its connection is dropped, and what
// it had not received is sent again when it resumes.
constexpr std::chrono::milliseconds kWriteStall{10000};
}  // namespace

bool read_message(Stream& stream, std::uint32_t max_size, std::atomic<bool> const& stop, Header& header, std::string& payload,
                  std::chrono::milliseconds idle) {
    char head[kHeaderSize];
    if (!stream.read_exact(head, kHeaderSize, stop, idle)) return false;
    header = decode_header({head, kHeaderSize}, max_size);
    payload.resize(header.size - kHeaderSize);
    return stream.read_exact(payload.data(), payload.size(), stop, idle);
}

Session::~Session() { end(false, "the door closed"); }

void Session::send(MessageType type, std::string_view payload) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::string bytes = state_.frame(type, payload);
    noted();
    write_locked(bytes);
}

bool Session::write_locked(std::string_view bytes) {
    if (!stream_) return false;
    if (stream_->write_all(bytes, kWriteStall)) return true;
    stream_->shutdown();  // its reader sees the end and drops the connection
    return false;
}

void Session::send_callback(std::string_view request) {
    std::unique_lock<std::mutex> lock(mutex_);
    confirmed_.wait(lock, [&] { return ended_ || state_.kept_bytes() < limits_.kept_budget; });
    if (ended_) return;
    const std::string bytes = state_.frame(MessageType::HlaCallbackRequest, request);
    noted();
    write_locked(bytes);
}

void Session::noted() {
    kept_bytes_ = state_.kept_bytes();
    connected_ = stream_ != nullptr;
}

void Session::serve(std::shared_ptr<Stream> stream) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stream_ = stream;
        noted();
        dropped_at_ = 0;
    }
    Header h;
    std::string payload;
    try {
        while (!ended_ && read_message(*stream, limits_.max_message, ended_, h, payload)) on_message(h, payload);
    } catch (BadMessage const& e) {
        std::fprintf(stderr, "fedpro: session %llu: %s; the session ends\n", (unsigned long long)id(), e.what());
        end(false, std::string("a bad message: ") + e.what());
    }
    drop(stream.get());
}

void Session::on_message(Header const& h, std::string_view payload) {
    bool fresh;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        fresh = state_.receive(h);
        noted();
    }
    confirmed_.notify_all();
    if (!fresh) return;  // sent again after a resume: done already
    switch (h.type) {
        case MessageType::Heartbeat:
            send(MessageType::HeartbeatResponse, u32s({h.sequence}));
            break;
        case MessageType::HlaCallRequest: {
            const std::string response = federate_->call(payload);
            send(MessageType::HlaCallResponse, u32s({h.sequence}) + response);
            break;
        }
        case MessageType::HlaCallbackResponse:
            payload_u32(payload, 0);  // the number of the callback answered: BadMessage when it is not there
            federate_->answered(payload.substr(4));
            break;
        case MessageType::TerminateSession:
            end(true, "terminated by the federate");
            break;
        default:
            throw BadMessage(std::string("a ") + name(h.type) + " within a session");
    }
}

void Session::drop(Stream const* stream) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stream_.get() == stream) {
        stream_.reset();
        noted();
        dropped_at_ = std::chrono::steady_clock::now().time_since_epoch().count();
    }
}

bool Session::resume(std::shared_ptr<Stream> stream, std::uint32_t last_received_by_federate) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (ended_) {
        stream->write_all(state_.first_frame(MessageType::ResumeStatus, u32s({kInvalidSession, kNoSequence})), kWriteStall);
        return false;
    }
    SessionState::Resume r = state_.resume(last_received_by_federate);
    if (stream_) stream_->shutdown();  // the old connection, when the federate saw the drop first
    stream_ = std::move(stream);
    write_locked(state_.frame(MessageType::ResumeStatus, u32s({r.status, state_.last_hla_received()})));
    if (r.status != kResumeOk) {
        stream_.reset();
        noted();
        lock.unlock();
        end(false, "a resume the session could not serve");
        return false;
    }
    ++resumes_;
    noted();
    for (auto const& bytes : r.resend)
        if (!write_locked(bytes)) break;  // dropped again: the next resume sends them
    return true;
}

std::chrono::steady_clock::duration Session::dropped_for(std::chrono::steady_clock::time_point now) const {
    const auto dropped = dropped_at_.load();
    if (ended_ || connected_ || dropped == 0) return {};
    return now - std::chrono::steady_clock::time_point(std::chrono::steady_clock::duration(dropped));
}

bool Session::expired(std::chrono::steady_clock::time_point now) const {
    return ended_ || dropped_for(now) > limits_.resume_timeout;
}

void Session::end(bool tell_federate, std::string const& reason) {
    std::lock_guard<std::mutex> once(ending_);
    if (ended_.exchange(true)) return;
    {
        std::lock_guard<std::mutex> lock(reason_mutex_);
        end_reason_ = reason;
    }
    confirmed_.notify_all();  // a callback waiting for room gives up
    if (federate_) federate_->end();
    std::lock_guard<std::mutex> lock(mutex_);
    if (tell_federate) write_locked(state_.frame(MessageType::SessionTerminated, {}));
    if (stream_) stream_->shutdown();  // its thread lets it go
}

std::string Session::status_json(std::chrono::steady_clock::time_point now) const {
    const auto [federation, federate] = federate_ ? federate_->member() : std::pair<std::string, std::string>{};
    char id[24];
    std::snprintf(id, sizeof id, "%016llx", (unsigned long long)state_.id());
    std::string json = std::string("{\"id\":\"") + id + "\",\"federation\":";
    json_string(json, federation);
    json += ",\"federate\":";
    json_string(json, federate);
    json += std::string(",\"state\":\"") + (ended_ ? "ended" : connected_ ? "connected" : "dropped") + '"';
    const double seconds = std::chrono::duration<double>(dropped_for(now)).count();
    json += ",\"dropped_seconds\":" + std::to_string(seconds) + ",\"kept_bytes\":" + std::to_string(kept_bytes_.load()) +
            ",\"resumes\":" + std::to_string(resumes_.load()) + ",\"reason\":";
    std::lock_guard<std::mutex> lock(reason_mutex_);
    json_string(json, end_reason_);
    return json + '}';
}

}  // namespace hlacore::fedpro
