// libFuzzer target for the gateway's datagram port (best effort over UDP, cpp/rti/server/datagrams.cpp):
// arbitrary datagram bodies from a joined federate whose datagram path is up.
//
// One Gateway runs on a background thread for the whole process (as in fuzz_gateway). For each input the
// target connects, says Hello, reads the Welcome (the connection's datagram token), creates federation "F"
// from cpp/fuzz/gateway.fed (an error reply when it exists) and joins it, proves the datagram path
// (DatagramHello echoed, DatagramPath), then sends the input as datagrams: the input's whole frames one per
// datagram (the wire seed corpus suits it), other bytes in pieces the input's bytes size. Every datagram
// carries the right token; the first input byte chooses how the sequence numbers go (steps, repeats, going
// back), to reach the loss and reorder counting. A QueryStatus round trip over the stream then shows the
// gateway alive. Failures: a crash, a sanitizer report, an exception escaping the gateway thread, or no
// answer within 10 s.
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <string>
#include <string_view>

#include "gateway_fixture.hpp"
#include "rti/wire/codec.hpp"
#include "rti/wire/datagram.hpp"

using namespace hlacore;
using fuzz_fixture::die;
using fuzz_fixture::fixture;

namespace {
unsigned counter = 0;

void send_all(int fd, const std::string& bytes) {
    for (std::size_t done = 0; done < bytes.size();) {
        const ssize_t n = ::send(fd, bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) die("send");
        done += static_cast<std::size_t>(n);
    }
}

// Reads frames from the stream until `done(message)` holds for one (true), or the gateway closes the
// stream (false); dies after 10 s without either.
template <class Done>
bool read_until(int fd, std::string& in, Done done) {
    char buffer[65536];
    for (;;) {
        wire::Frame frame;
        while (std::size_t used = wire::next_frame(in, frame)) {
            const bool found = done(wire::decode(frame));
            in.erase(0, used);
            if (found) return true;
        }
        pollfd p{fd, POLLIN, 0};
        const int ready = ::poll(&p, 1, 10000);
        if (ready < 0 && errno == EINTR) continue;
        if (ready <= 0) die("no answer from the gateway within 10 s");
        const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        in.append(buffer, static_cast<std::size_t>(n));
    }
}

// Whether m is an Answer (a typed result, or a Reply) to `request`.
template <class Answer>
bool answers(const wire::Message& m, std::uint32_t request) {
    const auto* answer = std::get_if<Answer>(&m);
    return answer && answer->request == request;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const int stream = fuzz_fixture::connect_stream(fixture.port);
    const int datagrams = ::socket(AF_INET, SOCK_DGRAM, 0);
    if (datagrams < 0) die("socket");
    fuzz_fixture::connect_to_gateway(datagrams, fixture.port);  // a UDP connect does not wait

    std::string in, out;
    std::uint64_t token = 0;
    wire::encode(out, wire::Hello{});
    send_all(stream, out);
    const bool welcomed = read_until(stream, in, [&](const wire::Message& m) {
        const auto* welcome = std::get_if<wire::Welcome>(&m);
        if (welcome) token = welcome->datagram_token;
        return welcome != nullptr;
    });
    if (!welcomed || token == 0) die("no Welcome with a datagram token");
    out.clear();
    wire::encode(out, wire::CreateFederation{1, 0, 0, "F", "gateway.fed", fixture.fed_text, ""});
    wire::encode(out, wire::JoinFederation{2, "d" + std::to_string(counter++), "F", ""});
    send_all(stream, out);
    bool joined = false;
    read_until(stream, in, [&](const wire::Message& m) {
        joined = answers<wire::FederationJoined>(m, 2);
        return joined || answers<wire::Reply>(m, 2);  // a Reply is a refusal
    });
    if (!joined) die("the join was refused");

    std::string hello;
    wire::put_datagram_header(hello, token, 0);
    wire::encode(hello, wire::DatagramHello{1});
    for (int attempt = 0;; ++attempt) {  // loopback loses nothing, but a full socket buffer may
        if (attempt == 10) die("no echo of the DatagramHello");
        ::send(datagrams, hello.data(), hello.size(), 0);
        pollfd p{datagrams, POLLIN, 0};
        if (::poll(&p, 1, 1000) > 0) {
            char echo[512];
            if (::recv(datagrams, echo, sizeof echo, 0) > 0) break;
        }
    }
    out.clear();
    wire::encode(out, wire::DatagramPath{});
    send_all(stream, out);

    const std::uint8_t mode = size ? data[0] : 0;
    std::string_view rest(reinterpret_cast<const char*>(data), size);
    if (!rest.empty()) rest.remove_prefix(1);
    std::uint64_t sequence = 0;
    for (unsigned k = 0; !rest.empty(); ++k) {
        wire::Frame frame;
        std::size_t piece = 0;
        try {
            piece = wire::next_frame(rest, frame, wire::kMaxDatagramLimit);
        } catch (const wire::WireError&) {
        }
        if (piece == 0) piece = std::min<std::size_t>(rest.size(), 1 + static_cast<unsigned char>(rest[0]));
        // The sequence: steps of 1 to 4, and with the mode's high bit every third datagram goes back.
        sequence = (mode & 0x80) && k % 3 == 2 && sequence > 2 ? sequence - 2 : sequence + 1 + (mode + k) % 4;
        std::string datagram;
        wire::put_datagram_header(datagram, token, sequence);
        datagram.append(rest.substr(0, piece));
        ::send(datagrams, datagram.data(), datagram.size(), MSG_DONTWAIT);
        rest.remove_prefix(piece);
    }

    out.clear();
    wire::encode(out, wire::QueryStatus{3});
    // The federate may have been dropped for a protocol error in a datagram: then the stream just closes.
    if (::send(stream, out.data(), out.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(out.size()))
        read_until(stream, in, [](const wire::Message& m) { return answers<wire::StatusReport>(m, 3); });
    ::close(datagrams);
    ::close(stream);
    return 0;
}
