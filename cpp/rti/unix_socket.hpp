// A gateway on the same host over a Unix socket (`rtig --unix PATH`, the address `unix:PATH`;
// docs/networking.md): the same byte stream as TCP without the TCP/IP stack under it. A send of a small
// message costs about half as much CPU, and a 16 MiB update travels at 1.5 times the bandwidth
// (docs/performance.md). No datagrams and no TLS: the socket never leaves the host, and its file's mode says
// who may connect.
#pragma once

#include <string>

#include <sys/un.h>

namespace hlacore::unix_socket {

// The prefix of a gateway address that names a Unix socket: "unix:/run/user/1000/rtig.sock".
inline constexpr char kPrefix[] = "unix:";

// Whether `address` (a host, or HOST:PORT) names a Unix socket.
bool is_unix(const std::string& address);
// The socket's path in such an address.
std::string path_of(const std::string& address);

// The socket address of `path`; std::invalid_argument when it is empty or longer than sun_path holds.
sockaddr_un address_of(const std::string& path);

// A non-blocking listening socket at `path`, its file readable and writable by its owner only (connecting
// needs write permission). A socket file that nothing listens on any more (a gateway that was killed) is
// replaced; one that a process still listens on is std::runtime_error, as is any other failure.
int listen_at(const std::string& path);

// Gives a connected Unix socket a send buffer as large as the system allows (net.core.wmem_max, 4 MiB at
// most): the default (net.core.wmem_default, 208 KiB) held back streams of small updates that TCP, whose
// buffer grows by itself, did not.
void size_send_buffer(int fd);

}  // namespace hlacore::unix_socket
