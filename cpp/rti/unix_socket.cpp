#include "rti/unix_socket.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

namespace hlacore::unix_socket {

bool is_unix(const std::string& address) { return address.rfind(kPrefix, 0) == 0; }

std::string path_of(const std::string& address) { return address.substr(sizeof kPrefix - 1); }

sockaddr_un address_of(const std::string& path) {
    sockaddr_un a{};
    if (path.empty()) throw std::invalid_argument("a Unix socket needs a path (unix:PATH)");
    if (path.size() >= sizeof a.sun_path)
        throw std::invalid_argument("the Unix socket path '" + path + "' is longer than the " +
                                    std::to_string(sizeof a.sun_path - 1) + " bytes a socket address holds");
    a.sun_family = AF_UNIX;
    std::memcpy(a.sun_path, path.data(), path.size());
    return a;
}

namespace {

std::runtime_error failure(const std::string& what, const std::string& path) {
    return std::runtime_error(what + " " + path + ": " + std::strerror(errno));
}

// Whether a process listens at `path` now (a connection to it succeeds).
bool listened_at(const sockaddr_un& a) {
    const int probe = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (probe < 0) return false;
    const bool connected = ::connect(probe, reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0;
    ::close(probe);
    return connected;
}

}  // namespace

int listen_at(const std::string& path) {
    const sockaddr_un a = address_of(path);
    struct stat existing {};
    if (::lstat(path.c_str(), &existing) == 0) {
        if (!S_ISSOCK(existing.st_mode))
            throw std::runtime_error("cannot listen on " + path + ": it exists and is not a socket");
        if (listened_at(a)) throw std::runtime_error("cannot listen on " + path + ": another process listens there");
        if (::unlink(path.c_str()) < 0) throw failure("cannot replace the stale socket", path);
    }
    const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (fd < 0) throw failure("cannot make a socket for", path);
    // The file is made with the mode the umask leaves; made owner-only before anyone may connect (listen).
    if (::bind(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) < 0 || ::chmod(path.c_str(), 0600) < 0 ||
        ::listen(fd, 128) < 0) {
        const std::runtime_error error = failure("cannot listen on", path);
        ::close(fd);
        throw error;
    }
    return fd;
}

void size_send_buffer(int fd) {
    constexpr int kWanted = 4 << 20;
    // The kernel caps the request at net.core.wmem_max (and doubles it for its bookkeeping).
    ::setsockopt(fd, SOL_SOCKET, SO_SNDBUF, &kWanted, sizeof kWanted);
}

}  // namespace hlacore::unix_socket
