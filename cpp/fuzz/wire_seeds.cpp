// wire_seeds DIR: writes one valid frame of every wire message into DIR/<Name>.bin, each field filled with
// a sample value. scripts/fuzz.sh and tests/system/test_fuzz.py give them to fuzz_wire and fuzz_gateway beside the
// hand-written seeds of make_wire_seeds.py, so a message appended to HLACORE_MESSAGES gets a seed (and the
// seed replay checks that it decodes and re-encodes to the same bytes) without anyone writing one.
#include <cstdio>
#include <cstdint>
#include <fstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "rti/wire/codec.hpp"

namespace {

using namespace hlacore::wire;

// Non-zero, non-empty values: a zero handle or an empty list would leave paths of the decoder unvisited.
struct Sampler {
    template <class... T>
    void operator()(T&... values) { (set(values), ...); }

    void set(bool& v) { v = true; }
    void set(std::uint8_t& v) { v = 1; }
    void set(std::uint16_t& v) { v = 1; }
    void set(std::uint32_t& v) { v = 2; }
    void set(std::uint64_t& v) { v = 3; }
    void set(double& v) { v = 1.5; }
    void set(std::string& s) { s = "sample"; }
    void set(Value& v) { v = "sample"; }
    void set(OptionalTime& t) { t = 2.5; }
    template <class T>
    void set(std::vector<T>& items) {
        items.resize(2);
        for (auto& item : items) set(item);
    }
    template <class A, class B>
    void set(std::pair<A, B>& p) {
        set(p.first);
        set(p.second);
    }
    template <class T, class = decltype(std::declval<T&>().fields(std::declval<Sampler&>()))>
    void set(T& record) {
        record.fields(*this);
    }
    template <class T>
    void set(Boxed<T>& boxed) {
        set(boxed.edit());
    }
};

template <std::size_t I = 1>
int write_all(const std::string& dir) {
    if constexpr (I == std::variant_size_v<Message>) {
        return 0;
    } else {
        std::variant_alternative_t<I, Message> message;
        message.fields(Sampler{});
        std::string frame;
        encode(frame, message);
        const std::string path = dir + "/" + message_name(static_cast<MessageType>(I)) + ".bin";
        std::ofstream out(path, std::ios::binary);
        out.write(frame.data(), static_cast<std::streamsize>(frame.size()));
        if (!out) {
            std::fprintf(stderr, "wire_seeds: cannot write %s\n", path.c_str());
            return 1;
        }
        return write_all<I + 1>(dir);
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: wire_seeds DIR\n");
        return 2;
    }
    return write_all(argv[1]);
}
