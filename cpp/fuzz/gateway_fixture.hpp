// What the gateway fuzz targets share: one Gateway on a background thread for the whole fuzzing process (its
// federations persist from input to input, like a long-running rtig), the FED its sessions create federation
// "F" from, and a connection to it that survives libFuzzer's timer signal.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "rti/server/gateway.hpp"

namespace fuzz_fixture {

[[noreturn]] inline void die(const char* what) {
    std::fprintf(stderr, "fuzzer: %s: %s\n", what, std::strerror(errno));
    std::abort();
}

struct Fixture {
    std::uint16_t port = 0;
    std::string fed_text;  // cpp/fuzz/gateway.fed: robot.fed's handles plus routing spaces (DDM is reached too)
};

// Reads the FED and starts the gateway (LLVMFuzzerInitialize).
inline Fixture start_gateway() {
    Fixture fixture;
    std::ifstream in(HLACORE_SOURCE_DIR "/cpp/fuzz/gateway.fed");
    std::stringstream text;
    text << in.rdbuf();
    fixture.fed_text = text.str();
    if (fixture.fed_text.empty()) die("cannot read cpp/fuzz/gateway.fed");
    hlacore::GatewayOptions options;
    options.host = "127.0.0.1";
    options.port = 0;
    auto* gateway = new hlacore::Gateway(options);  // lives as long as the process
    fixture.port = gateway->port();
    std::thread([gateway] { gateway->run(); }).detach();
    return fixture;
}

inline sockaddr_in gateway_address(std::uint16_t port) {
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(port);
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    return addr;
}

// Connects `fd` to the gateway. libFuzzer's timer signal can interrupt a connect that waits (a busy
// machine, a full backlog): the connection goes on, so wait until it is made (seen in CI: "connect:
// Interrupted system call").
inline void connect_to_gateway(int fd, std::uint16_t port) {
    const sockaddr_in addr = gateway_address(port);
    if (::connect(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) == 0) return;
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

// A TCP connection to the gateway with Nagle off (or each request waits for a delayed ACK).
inline int connect_stream(std::uint16_t port) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) die("socket");
    connect_to_gateway(fd, port);
    int one = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    return fd;
}

// This target's gateway (a target includes this header once), started by libFuzzer's initialization hook.
inline Fixture fixture;

}  // namespace fuzz_fixture

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    fuzz_fixture::fixture = fuzz_fixture::start_gateway();
    return 0;
}
