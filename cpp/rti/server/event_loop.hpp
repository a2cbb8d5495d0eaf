// A thin epoll wrapper: register file descriptors, wait for readiness. Single-threaded by design.
#pragma once

#include <cstdint>
#include <vector>

#include <sys/epoll.h>

namespace hlacore {

class EventLoop {
public:
    EventLoop();
    ~EventLoop();
    EventLoop(const EventLoop&) = delete;
    EventLoop& operator=(const EventLoop&) = delete;

    void add(int fd, std::uint32_t events);
    void modify(int fd, std::uint32_t events);
    void remove(int fd);

    // Waits up to timeout_ms (-1: forever) and returns the ready events; EINTR yields an empty list.
    const std::vector<epoll_event>& wait(int timeout_ms);

private:
    int epoll_fd_;
    std::vector<epoll_event> ready_;
};

}  // namespace hlacore
