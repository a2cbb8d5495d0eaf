// Where a federation's service groups write what they send to federates: the output buffers of the
// gateway's connections (gateway_internal.hpp), held back while a federate saves or restores (save_restore.cpp).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "rti/wire/codec.hpp"

namespace hlacore {

using FederateHandle = std::uint32_t;
using ObjectHandle = std::uint32_t;

// Shortest text that reads back as the same double, for error messages.
std::string time_text(double t);

// Whoever records the callbacks a federation sends (server/recorder.hpp).
class CallbackRecorder {
public:
    virtual ~CallbackRecorder() = default;
    virtual void callback(FederateHandle to, const wire::Message& message) = 0;
};

// The callbacks a recording keeps: all but reflections and received interactions (directed too), whose content it
// has from their sender's request.
template <class M>
constexpr bool kRecordedCallback = M::kType != wire::MessageType::ReflectAttributes &&
                                   M::kType != wire::MessageType::ReceiveInteraction &&
                                   M::kType != wire::MessageType::ReceiveDirectedInteraction;

template <class M>
constexpr bool kForwarded = std::is_same_v<M, wire::ForwardedReflection> || std::is_same_v<M, wire::ForwardedInteraction>;

// Where a federation writes the frames it sends: the output buffer of a federate's connection.
class Outbox {
public:
    virtual ~Outbox() = default;
    virtual std::string& buffer(FederateHandle federate) = 0;

    template <class M>
    void send(FederateHandle federate, const M& message) {
        if (holding) {  // a save or restore is under way: see server/save_restore.cpp
            auto held = holding->find(federate);
            if (held != holding->end()) {
                record(federate, message);
                wire::encode(held->second.emplace_back(), message);
                return;
            }
        }
        send_unheld(federate, message);
    }
    // What is never held back by a save or restore: time management's releases, the save's own callbacks.
    template <class M>
    void send_unheld(FederateHandle federate, const M& message) {
        record(federate, message);
        if constexpr (kForwarded<M>) {
            if (wire::has_spliced_value(message.values) && send_spliced(federate, message)) return;
        }
        wire::encode(buffer(federate), message);
    }
    // A forwarded update or interaction with a large value, written with its large values referenced where
    // they were read (the gateway's splices, server/connection.hpp); false: the caller copies it.
    virtual bool send_spliced(FederateHandle federate, const wire::ForwardedReflection& message) {
        (void)federate, (void)message;
        return false;
    }
    virtual bool send_spliced(FederateHandle federate, const wire::ForwardedInteraction& message) {
        (void)federate, (void)message;
        return false;
    }
    void send_frame(FederateHandle federate, const std::string& frame) { buffer(federate).append(frame); }
    // Frames released at once (held messages): the gateway writes them as the federate takes them, freeing
    // each on the way, rather than copying them all into its output buffer (docs/robustness.md).
    virtual void send_frames(FederateHandle federate, std::vector<wire::SharedFrame>& frames) {
        std::string& out = buffer(federate);
        for (const auto& frame : frames) out.append(*frame);
    }
    // A best-effort receive-order message: sent as a datagram when the federate takes them and it fits
    // (server/datagrams.cpp); false: the caller sends it in the stream.
    template <class M>
    bool send_best_effort(FederateHandle federate, const M& message) {
        if ((holding && holding->count(federate)) || !takes_datagrams(federate)) return false;
        thread_local std::string frame;  // in-process gateways may run on several threads
        frame.clear();
        wire::encode(frame, message);
        return send_datagram(federate, frame);
    }
    virtual bool takes_datagrams(FederateHandle federate) const { (void)federate; return false; }
    virtual bool send_datagram(FederateHandle federate, std::string_view frame) { (void)federate; (void)frame; return false; }
    // A message for `federate` was kept in the federation instead (time management holds it): the gateway
    // weighs it against the federate's budget like its output buffer.
    virtual void held(FederateHandle federate) { (void)federate; }
    // A restore gives the joined federates the handles they had in the save: old handle -> new handle.
    virtual void rehandle(const std::map<FederateHandle, FederateHandle>& new_handles) { (void)new_handles; }
    // While set, what send() would write for a federate with an entry here is kept there instead (the
    // federate is saving or restoring); buffer() and send_frame() are not held.
    std::map<FederateHandle, std::vector<std::string>>* holding = nullptr;
    // Set while the gateway records its federations (rtig --record).
    CallbackRecorder* recorder = nullptr;
    // Hands a callback to the recorder, if any: send() does; time management calls it for the callbacks it
    // queues (recorded when queued, not when released).
    template <class M>
    void record(FederateHandle federate, const M& message) {
        if constexpr (kRecordedCallback<M>) {
            if (recorder) recorder->callback(federate, message);
        }
    }
};

}  // namespace hlacore
