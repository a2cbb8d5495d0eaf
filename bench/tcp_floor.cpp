// The C++ floor of the benchmarks: raw TCP over loopback between two processes (this one and a forked
// child), with TCP_NODELAY as hlacore's sockets have; with --unix, a Unix socket pair (the floor of
// federates on the gateway's host, rtig --unix); with --spin (rtt, rtt-relay, barrier), every process polls instead
// of sleeping in recv (the floor of busy-polling processes: no wake-up, so not bimodal as the sleeping round
// trip is between one core and two). Prints one JSON line.
//
//   tcp_floor rtt SIZE COUNT       COUNT round trips of SIZE bytes (after 200 unmeasured):
//                                  {"rtt_ns": [each round trip in ns, in order]}
//   tcp_floor rtt-relay SIZE COUNT the same through a third process that passes each message on, both ways:
//                                  four hops, as an update and its echo through a gateway take
//   tcp_floor barrier SIZE COUNT   the same through a server that answers this process and a second client
//                                  once both have sent, as the rtig grants two federates in lockstep
//   tcp_floor stream RECORD COUNT  COUNT records of RECORD bytes, one send() each, until the child has
//                                  counted them all and answered one byte: {"seconds": s, "count": COUNT}
//   tcp_floor relay RECORD COUNT   the same through a third process that forwards every byte as it comes
//                                  (recv into one buffer, send it on): the floor of any design that routes
//                                  through a server, three processes and four copies in the kernel
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <sched.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
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

// --spin: every read polls (MSG_DONTWAIT, yielding the core between tries) instead of sleeping, as hlacore's
// busy polling does (cpp/rti/busy_poll.hpp).
int read_flags = 0;

// Reads exactly n bytes; false on EOF.
bool read_exact(int fd, char* p, std::size_t n) {
    while (n > 0) {
        ssize_t r = recv(fd, p, n, read_flags);
        if (r == 0) return false;
        if (r < 0) {
            if (errno == EAGAIN) sched_yield();  // a third polling process may share this core
            if (errno == EINTR || errno == EAGAIN) continue;
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

// A connected pair of stream sockets, one end for each of two processes: over TCP loopback (TCP_NODELAY, as
// hlacore's sockets have) or, with --unix, a Unix socket pair (4 MiB send buffers, as hlacore's Unix socket
// ends have: the default 208 KiB would throttle the stream modes).
struct Link {
    int near = -1;  // the parent's end (on the second link of a relay, the relay's)
    int far = -1;   // the other process's end
};

Link make_link(bool unix_socket) {
    Link link;
    if (unix_socket) {
        int ends[2];
        if (socketpair(AF_UNIX, SOCK_STREAM, 0, ends) != 0) die("socketpair");
        const int size = 4 << 20;
        for (int fd : ends)
            if (setsockopt(fd, SOL_SOCKET, SO_SNDBUF, &size, sizeof size) != 0) die("setsockopt");
        link.near = ends[0];
        link.far = ends[1];
        return link;
    }
    int listener = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof addr;
    if (bind(listener, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 || listen(listener, 1) != 0 ||
        getsockname(listener, reinterpret_cast<sockaddr*>(&addr), &len) != 0)
        die("listen");
    link.near = socket(AF_INET, SOCK_STREAM, 0);  // the handshake completes in the backlog: no second thread
    if (connect(link.near, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0) die("connect");
    link.far = accept(listener, nullptr, nullptr);
    if (link.far < 0) die("accept");
    close(listener);
    for (int fd : {link.near, link.far}) nodelay(fd);
    return link;
}

// In a forked process: closes every end of `links` but `keep`, so each end's EOF reaches its peer.
void keep_only(const std::vector<Link>& links, std::initializer_list<int> keep) {
    for (const Link& link : links)
        for (int fd : {link.near, link.far})
            if (std::find(keep.begin(), keep.end(), fd) == keep.end()) close(fd);
}

// In a forked process, once its part is done: closes its ends and exits 0, the status the parent checks.
[[noreturn]] void finish(std::initializer_list<int> fds) {
    for (int fd : fds) close(fd);
    std::exit(0);
}

// The relay: forwards `total` bytes from the parent to the sink, then the sink's answer back, then waits for
// the parent's EOF.
[[noreturn]] void relay(int from, int to, std::size_t total) {
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
    finish({to, from});
}

// The round-trip relay: passes each SIZE-byte message from the parent to the echo and its echo back, until
// the parent's EOF.
[[noreturn]] void rtt_relay(int from, int to, std::size_t size) {
    std::vector<char> buf(size);
    while (read_exact(from, buf.data(), size)) {
        write_all(to, buf.data(), size);
        if (!read_exact(to, buf.data(), size)) die("relay: echo closed");
        write_all(from, buf.data(), size);
    }
    finish({to, from});
}

// The barrier's server: waits for a SIZE-byte message from each of its two clients, then answers both (as the
// rtig grants two federates once both have asked), until the parent's EOF.
[[noreturn]] void barrier_server(int parent, int peer, std::size_t size) {
    std::vector<char> buf(size);
    while (read_exact(parent, buf.data(), size)) {
        if (!read_exact(peer, buf.data(), size)) die("barrier: peer closed");
        write_all(parent, buf.data(), size);
        write_all(peer, buf.data(), size);
    }
    // The peer has asked once more: end its wait with an EOF, and read it to its own EOF before closing, as
    // closing with its request unread would reset the connection under it.
    shutdown(peer, SHUT_WR);
    while (recv(peer, buf.data(), size, 0) > 0) {
    }
    finish({parent, peer});
}

// The barrier's other client: asks and waits for the answer, as the parent does, until the server's EOF.
[[noreturn]] void barrier_peer(int fd, std::size_t size) {
    std::vector<char> buf(size, 'y');
    while (write_all(fd, buf.data(), size), read_exact(fd, buf.data(), size)) {
    }
    finish({fd});
}

// The child: echo SIZE-byte messages or count RECORD-byte records.
[[noreturn]] void child(int fd, bool stream, std::size_t size, long count) {
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
    finish({fd});
}

}  // namespace

int main(int argc, char** argv) {
    bool unix_socket = false;
    for (; argc > 1 && argv[1][0] == '-'; ++argv, --argc) {
        if (std::string(argv[1]) == "--unix") {
            unix_socket = true;
        } else if (std::string(argv[1]) == "--spin") {
            read_flags = MSG_DONTWAIT;
        } else {
            argc = 0;  // a usage error below
            break;
        }
    }
    const std::string mode = argc == 4 ? argv[1] : "";
    const bool stream = mode == "stream" || mode == "relay";
    const bool barrier = mode == "barrier";
    if ((mode != "rtt" && mode != "rtt-relay" && !barrier && !stream) ||
        (read_flags != 0 && stream)) {
        std::fprintf(stderr, "usage: tcp_floor [--unix] [--spin] rtt|rtt-relay|barrier SIZE COUNT | tcp_floor [--unix] stream|relay RECORD COUNT\n");
        return 2;
    }
    const bool relayed = mode == "relay" || mode == "rtt-relay";
    const std::size_t size = std::strtoul(argv[2], nullptr, 10);
    const long count = std::strtol(argv[3], nullptr, 10);
    if (size == 0 || count <= 0) return 2;

    // parent -> child, or parent -> relay -> child, or parent -> barrier server <- peer
    std::vector<Link> links{make_link(unix_socket)};
    if (relayed || barrier) links.push_back(make_link(unix_socket));
    std::vector<pid_t> children;
    pid_t pid = fork();
    if (pid < 0) die("fork");
    if (pid == 0 && barrier) {
        keep_only(links, {links[0].far, links[1].far});
        barrier_server(links[0].far, links[1].far, size);
    }
    if (pid == 0) {
        keep_only(links, {links.back().far});
        child(links.back().far, stream, size, count);
    }
    children.push_back(pid);
    if (barrier) {
        pid = fork();
        if (pid < 0) die("fork");
        if (pid == 0) {
            keep_only(links, {links[1].near});
            barrier_peer(links[1].near, size);
        }
        children.push_back(pid);
    }
    if (relayed) {
        const int from = links[0].far, to = links[1].near;
        pid = fork();
        if (pid < 0) die("fork");
        if (pid == 0) {
            keep_only(links, {from, to});
            if (stream) relay(from, to, size * static_cast<std::size_t>(count));
            rtt_relay(from, to, size);
        }
        children.push_back(pid);
    }
    const int fd = links[0].near;
    keep_only(links, {fd});

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
