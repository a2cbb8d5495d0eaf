// The C++ floor of the benchmarks: raw TCP over loopback between two processes (this one and a forked
// child), with TCP_NODELAY as hlacore's sockets have. Prints one JSON line.
//
//   tcp_floor rtt SIZE COUNT       COUNT round trips of SIZE bytes (after 200 unmeasured):
//                                  {"rtt_ns": [each round trip in ns, in order]}
//   tcp_floor rtt-relay SIZE COUNT the same through a third process that passes each message on, both ways:
//                                  four hops, as an update and its echo through a gateway take
//   tcp_floor stream RECORD COUNT  COUNT records of RECORD bytes, one send() each, until the child has
//                                  counted them all and answered one byte: {"seconds": s, "count": COUNT}
//   tcp_floor relay RECORD COUNT   the same through a third process that forwards every byte as it comes
//                                  (recv into one buffer, send it on): the floor of any design that routes
//                                  through a server, three processes and four copies in the kernel
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

[[noreturn]] void die(const char* what) {
    std::fprintf(stderr, "tcp_floor: %s: %s\n", what, std::strerror(errno));
    std::exit(2);
}

void nodelay(int fd) {
    int one = 1;
    if (setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one) != 0) die("setsockopt");
}

// Reads exactly n bytes; false on EOF.
bool read_exact(int fd, char* p, std::size_t n) {
    while (n > 0) {
        ssize_t r = recv(fd, p, n, 0);
        if (r == 0) return false;
        if (r < 0) {
            if (errno == EINTR) continue;
            die("recv");
        }
        p += r;
        n -= static_cast<std::size_t>(r);
    }
    return true;
}

void write_all(int fd, const char* p, std::size_t n) {
    while (n > 0) {
        ssize_t w = send(fd, p, n, MSG_NOSIGNAL);
        if (w < 0) {
            if (errno == EINTR) continue;
            die("send");
        }
        p += w;
        n -= static_cast<std::size_t>(w);
    }
}

int listen_loopback(sockaddr_in& addr) {
    int listener = socket(AF_INET, SOCK_STREAM, 0);
    addr = sockaddr_in{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof addr;
    if (bind(listener, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 || listen(listener, 1) != 0 ||
        getsockname(listener, reinterpret_cast<sockaddr*>(&addr), &len) != 0)
        die("listen");
    return listener;
}

int connect_to(const sockaddr_in& addr) {
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    if (connect(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0) die("connect");
    nodelay(fd);
    return fd;
}

int accept_one(int listener) {
    int fd = accept(listener, nullptr, nullptr);
    if (fd < 0) die("accept");
    close(listener);
    nodelay(fd);
    return fd;
}

// The relay: forwards `total` bytes from the parent to the sink, then the sink's answer back, then waits for
// the parent's EOF.
[[noreturn]] void relay(int listener, const sockaddr_in& sink, std::size_t total) {
    int from = accept_one(listener);
    int to = connect_to(sink);
    std::vector<char> buf(1 << 20);
    for (std::size_t moved = 0; moved < total;) {
        ssize_t r = recv(from, buf.data(), std::min(buf.size(), total - moved), 0);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) die("relay recv");
        write_all(to, buf.data(), static_cast<std::size_t>(r));
        moved += static_cast<std::size_t>(r);
    }
    char ack;
    if (!read_exact(to, &ack, 1)) die("relay: sink closed");
    write_all(from, &ack, 1);
    read_exact(from, &ack, 1);  // EOF from the parent
    close(to);
    close(from);
    std::exit(0);
}

// The round-trip relay: passes each SIZE-byte message from the parent to the echo and its echo back, until
// the parent's EOF.
[[noreturn]] void rtt_relay(int listener, const sockaddr_in& echo, std::size_t size) {
    int from = accept_one(listener);
    int to = connect_to(echo);
    std::vector<char> buf(size);
    while (read_exact(from, buf.data(), size)) {
        write_all(to, buf.data(), size);
        if (!read_exact(to, buf.data(), size)) die("relay: echo closed");
        write_all(from, buf.data(), size);
    }
    close(to);
    close(from);
    std::exit(0);
}

// The child: accept one connection, then echo SIZE-byte messages or count RECORD-byte records.
[[noreturn]] void child(int listener, bool stream, std::size_t size, long count) {
    int fd = accept_one(listener);
    std::vector<char> buf(stream ? 1 << 20 : size);
    if (!stream) {
        while (read_exact(fd, buf.data(), size)) write_all(fd, buf.data(), size);
    } else {
        const std::size_t want = size * static_cast<std::size_t>(count);
        std::size_t got = 0;
        while (got < want) {
            ssize_t r = recv(fd, buf.data(), buf.size(), 0);
            if (r <= 0) die("recv");
            got += static_cast<std::size_t>(r);
        }
        write_all(fd, "!", 1);
        read_exact(fd, buf.data(), 1);  // EOF from the parent
    }
    close(fd);
    std::exit(0);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string mode = argc == 4 ? argv[1] : "";
    if (mode != "rtt" && mode != "rtt-relay" && mode != "stream" && mode != "relay") {
        std::fprintf(stderr, "usage: tcp_floor rtt|rtt-relay SIZE COUNT | tcp_floor stream|relay RECORD COUNT\n");
        return 2;
    }
    const bool stream = mode == "stream" || mode == "relay";
    const std::size_t size = std::strtoul(argv[2], nullptr, 10);
    const long count = std::strtol(argv[3], nullptr, 10);
    if (size == 0 || count <= 0) return 2;

    sockaddr_in addr{};
    int listener = listen_loopback(addr);
    std::vector<pid_t> children;
    pid_t pid = fork();
    if (pid < 0) die("fork");
    if (pid == 0) child(listener, stream, size, count);
    close(listener);
    children.push_back(pid);
    if (mode == "relay" || mode == "rtt-relay") {
        const sockaddr_in sink = addr;
        listener = listen_loopback(addr);
        pid = fork();
        if (pid < 0) die("fork");
        if (pid == 0 && stream) relay(listener, sink, size * static_cast<std::size_t>(count));
        if (pid == 0) rtt_relay(listener, sink, size);
        close(listener);
        children.push_back(pid);
    }

    int fd = connect_to(addr);
    std::vector<char> buf(size, 'x');
    std::string out;
    if (!stream) {
        std::vector<long long> samples;
        samples.reserve(static_cast<std::size_t>(count));
        for (long i = 0; i < count + 200; ++i) {
            auto start = Clock::now();
            write_all(fd, buf.data(), size);
            if (!read_exact(fd, buf.data(), size)) die("echo closed");
            auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - start).count();
            if (i >= 200) samples.push_back(ns);
        }
        out = "{\"rtt_ns\": [";
        for (std::size_t i = 0; i < samples.size(); ++i) out += (i ? "," : "") + std::to_string(samples[i]);
        out += "]}";
    } else {
        auto start = Clock::now();
        for (long i = 0; i < count; ++i) write_all(fd, buf.data(), size);
        char ack;
        if (!read_exact(fd, &ack, 1)) die("sink closed");
        double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        out = "{\"seconds\": " + std::to_string(seconds) + ", \"count\": " + std::to_string(count) + "}";
    }
    close(fd);
    for (pid_t child_pid : children) {
        int status = 0;
        if (waitpid(child_pid, &status, 0) != child_pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            std::fprintf(stderr, "tcp_floor: child failed\n");
            return 1;
        }
    }
    std::puts(out.c_str());
    return 0;
}
