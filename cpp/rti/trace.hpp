// The gateway's message trace (`rtig --trace FILE`): when each update and interaction arrived from its
// sender, and when each reflection of it was handed to a receiver's socket, on the host's monotonic clock
// (CLOCK_MONOTONIC, which Python's time.monotonic() reads too). With the federates' own marks this splits
// the way of a message into its hops: sender -> gateway, inside the gateway, gateway -> receiver (paper 2's
// C_RTI^emb, t_cycle^RTI and C_PT^RTI). Off by default; costs a clock read per read() and a decode per
// traced frame when on.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <type_traits>

#include "rti/wire/codec.hpp"

namespace hlacore {

class MessageTrace {
public:
    // Creates (truncates) the CSV file and writes its header; throws std::runtime_error when it cannot.
    explicit MessageTrace(const std::string& path);
    ~MessageTrace();
    MessageTrace(const MessageTrace&) = delete;
    MessageTrace& operator=(const MessageTrace&) = delete;

    static std::int64_t now_ns();

    void joined(const std::string& federation, std::uint32_t federate, const std::string& name, std::int64_t ns);
    // An update or interaction from `sender` read at `ns`, as the gateway serves it; other messages are not traced.
    template <class M>
    void received(const std::string& federation, std::uint32_t sender, const M& m, std::int64_t ns) {
        if constexpr (std::is_same_v<M, wire::UpdateAttributesView>)
            row(ns, "update", federation, sender, sender, m.serial, m.time, "");
        else if constexpr (std::is_same_v<M, wire::SendInteractionView>)
            row(ns, "interaction", federation, sender, sender, m.serial, m.time, "");
    }
    // `frames` are about to be written to `receiver`'s socket: records the reflections and interactions among
    // them. Returns the bytes of the whole frames, where the next call starts (a frame read back from a spill
    // file may come in two parts).
    std::size_t sending(const std::string& federation, std::uint32_t receiver, std::string_view frames, std::int64_t ns);
    // Writes out what is buffered (the gateway calls it once per turn of its loop).
    void flush();

private:
    void row(std::int64_t ns, const char* event, const std::string& federation, std::uint32_t federate,
             std::uint32_t sender, std::uint64_t serial, const wire::OptionalTime& time, const std::string& name);

    std::FILE* file_ = nullptr;
    bool unflushed_ = false;
};

}  // namespace hlacore
