#include "rti/trace.hpp"

#include <cerrno>
#include <cstring>
#include <ctime>
#include <stdexcept>

namespace hlacore {

namespace {

// RFC 4180 quoting, only where needed: names are free text.
std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char ch : text) {
        if (ch == '"') quoted += '"';
        quoted += ch;
    }
    return quoted + '"';
}

}  // namespace

MessageTrace::MessageTrace(const std::string& path) : file_(std::fopen(path.c_str(), "w")) {
    if (!file_) throw std::runtime_error("cannot write the trace file " + path + ": " + std::strerror(errno));
    std::fputs("ns,event,federation,federate,sender,serial,time,name\n", file_);
    std::fflush(file_);
}

MessageTrace::~MessageTrace() {
    if (file_) std::fclose(file_);
}

std::int64_t MessageTrace::now_ns() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<std::int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

void MessageTrace::row(std::int64_t ns, const char* event, const std::string& federation, std::uint32_t federate,
                       std::uint32_t sender, std::uint64_t serial, const wire::OptionalTime& time,
                       const std::string& name) {
    std::fprintf(file_, "%lld,%s,%s,%u,", static_cast<long long>(ns), event, csv_field(federation).c_str(), federate);
    if (sender) std::fprintf(file_, "%u", sender);
    std::fputc(',', file_);
    if (serial) std::fprintf(file_, "%llu", static_cast<unsigned long long>(serial));
    std::fputc(',', file_);
    if (time) std::fprintf(file_, "%.17g", *time);
    std::fprintf(file_, ",%s\n", csv_field(name).c_str());
    unflushed_ = true;
}

void MessageTrace::joined(const std::string& federation, std::uint32_t federate, const std::string& name,
                          std::int64_t ns) {
    row(ns, "join", federation, federate, 0, 0, std::nullopt, name);
}

std::size_t MessageTrace::sending(const std::string& federation, std::uint32_t receiver, std::string_view frames,
                                  std::int64_t ns) {
    wire::Frame frame;
    std::size_t traced = 0;
    while (std::size_t used = wire::next_frame(frames, frame)) {
        frames.remove_prefix(used);
        traced += used;
        if (frame.type == wire::MessageType::ReflectAttributes) {
            const auto m = std::get<wire::ReflectAttributes>(wire::decode(frame));
            row(ns, "reflect", federation, receiver, m.sender, m.serial, m.time, "");
        } else if (frame.type == wire::MessageType::ReceiveInteraction) {
            const auto m = std::get<wire::ReceiveInteraction>(wire::decode(frame));
            row(ns, "receive", federation, receiver, m.sender, m.serial, m.time, "");
        }
    }
    return traced;
}

void MessageTrace::flush() {
    if (!unflushed_) return;
    std::fflush(file_);
    unflushed_ = false;
}

}  // namespace hlacore
