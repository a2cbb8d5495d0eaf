// libFuzzer target for a whole gateway session: arbitrary bytes sent by a joined federate to a real Gateway.
//
// One Gateway runs on a background thread for the whole fuzzing process (its federations persist from input
// to input, like a long-running rtig). For each input the target connects, sends a Hello, creates federation
// "F" from cpp/fuzz/gateway.fed (robot.fed's handles plus routing spaces, so that DDM is reached too; an
// error reply when it exists), joins it under a fresh name, then sends the input's bytes (normally frames:
// the wire seed corpus suits it), a QueryStatus, and shuts its sending side. It then reads until the
// gateway closes the connection. Failures: a crash, a sanitizer report, an exception escaping the gateway
// thread (std::terminate), or the gateway not closing within 10 s (a hang).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "rti/server/gateway.hpp"
#include "rti/wire/codec.hpp"

using namespace hlacore;

namespace {
std::uint16_t port = 0;
std::string fed_text;
unsigned counter = 0;

[[noreturn]] void die(const char* what) {
    std::fprintf(stderr, "fuzz_gateway: %s: %s\n", what, std::strerror(errno));
    std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    std::ifstream in(HLACORE_SOURCE_DIR "/cpp/fuzz/gateway.fed");
    std::stringstream text;
    text << in.rdbuf();
    fed_text = text.str();
    if (fed_text.empty()) die("cannot read cpp/fuzz/gateway.fed");
    GatewayOptions options;
    options.host = "127.0.0.1";
    options.port = 0;
    auto* gateway = new Gateway(options);  // lives as long as the process
    port = gateway->port();
    std::thread([gateway] { gateway->run(); }).detach();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) die("socket");
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(port);
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
        // libFuzzer's timer signal can interrupt a connect that waits (a busy machine, a full backlog):
        // the connection goes on, so wait until it is made (seen in CI: "connect: Interrupted system call").
        if (errno != EINTR) die("connect");
        pollfd p{fd, POLLOUT, 0};
        while (::poll(&p, 1, 10000) < 0)
            if (errno != EINTR) die("poll after an interrupted connect");
        int error = 0;
        socklen_t length = sizeof error;
        getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &length);
        if (error != 0) {
            errno = error;
            die("connect");
        }
    }
    int one = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);

    std::string out;
    wire::encode(out, wire::Hello{});
    wire::encode(out, wire::CreateFederation{1, "F", "gateway.fed", fed_text});
    wire::encode(out, wire::JoinFederation{2, "f" + std::to_string(counter++), "F"});
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
