// libFuzzer target for a whole gateway session: arbitrary bytes sent by a joined federate to a real Gateway.
//
// One Gateway runs on a background thread for the whole fuzzing process (its federations persist from input
// to input, like a long-running rtig). For each input the target connects, sends a Hello, creates federation
// "F" from cpp/fuzz/gateway.fed (robot.fed's handles plus routing spaces, so that DDM is reached too; an
// error reply when it exists), joins it under a fresh name, then sends the input's bytes (normally frames:
// the wire seed corpus suits it), a QueryStatus, and shuts its sending side. It then reads until the
// gateway closes the connection. Failures: a crash, a sanitizer report, an exception escaping the gateway
// thread (std::terminate), or the gateway not closing within 10 s (a hang).
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <string>

#include "gateway_fixture.hpp"
#include "rti/wire/codec.hpp"

using namespace hlacore;
using fuzz_fixture::die;
using fuzz_fixture::fixture;

namespace {
unsigned counter = 0;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const int fd = fuzz_fixture::connect_stream(fixture.port);

    std::string out;
    wire::encode(out, wire::Hello{});
    wire::encode(out, wire::CreateFederation{1, 0, 0, "F", "gateway.fed", fixture.fed_text, ""});
    wire::encode(out, wire::JoinFederation{2, "f" + std::to_string(counter++), "F", ""});
    out.append(reinterpret_cast<const char*>(data), size);
    wire::encode(out, wire::QueryStatus{3});
    // Read while sending, so that a large answer cannot block both sides.
    bool sent = false;
    std::size_t offset = 0;
    char buffer[65536];
    for (int waited_ms = 0;;) {
        if (!sent) {
            const ssize_t n = ::send(fd, out.data() + offset, out.size() - offset, MSG_NOSIGNAL | MSG_DONTWAIT);
            if (n > 0) offset += static_cast<std::size_t>(n);
            if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) sent = true;  // dropped by the gateway
            if (offset == out.size()) sent = true;
            if (sent) ::shutdown(fd, SHUT_WR);
        }
        pollfd p{fd, POLLIN, 0};
        const int ready = ::poll(&p, 1, sent ? 100 : 1);
        if (ready == 0) {
            if (sent && (waited_ms += 100) > 10000) die("the gateway neither answered nor closed within 10 s");
            continue;
        }
        const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
        if (n == 0 || (n < 0 && errno == ECONNRESET)) break;  // closed: the session is over
        waited_ms = 0;
    }
    ::close(fd);
    return 0;
}
