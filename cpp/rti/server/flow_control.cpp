// The gateway's flow control (docs/robustness.md): what it holds for each client, pausing the clients that
// send to one over its budget, dropping readers that stalled and partial frames that never completed, and
// giving large buffers back.
#include "rti/server/gateway.hpp"
#include "rti/server/gateway_internal.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <openssl/ssl.h>

namespace hlacore {

bool Gateway::keeping_large_buffers() const {
    return large_buffers_kept_ && Clock::now() - large_frame_at_ < kLargeFrameGrace;
}

void Gateway::release_large_buffers() {
    bool in_use = false;  // a large buffer not empty yet: tried again on the next turn of the loop
    for (auto& [fd, c] : connections_) {
        c->in.release_above(kKeptBufferBytes);
        if (c->unsent() == 0 && c->out.capacity() > kKeptBufferBytes) {
            std::string().swap(c->out);
            c->out_offset = 0;
        }
        // A splice still to write pins a sender's read block, perhaps of a connection closed since.
        in_use |= c->in.capacity() > kKeptBufferBytes || c->out.capacity() > kKeptBufferBytes || !c->splices.empty();
    }
    large_buffers_kept_ = in_use;
#if defined(__GLIBC__)
    // Once per burst of large frames, when all is given back: the decoded values were freed below the top of
    // the heap, where glibc keeps up to twice the largest for reuse (tests/transport/test_large_values.py measures it).
    if (!in_use) malloc_trim(0);
#endif
}

bool Gateway::spill(Connection& c) {
    if (!c.spill_failed.empty()) return true;  // dropped at the end of the turn: what it is sent goes nowhere
    // A client whose own requests made more than it reads is held back instead (it asks more than it reads:
    // being served, or paused for its own queue); so are the senders to one that is taking what it is sent,
    // only slower: waiting for it a few milliseconds costs less than writing to disk and reading back.
    const bool own_requests = c.fd == serving_ || (c.paused && c.blocked_by == c.fd);
    if (!spill_budget_.on() || (!c.spill && (own_requests || !stopped_reading(c))))
        return held_for(c) <= options_.client_budget;
    try {
        if (!c.spill) {
            c.spill = std::make_unique<SpillFile>(spill_budget_);
            c.inline_splices();  // large values it was sent by reference pin their senders' read blocks
            // The stream is out, backlog, spill, tail: what `out` holds beyond what the client takes next (past
            // what the trace has seen) and the backlog go to the file first.
            const std::size_t keep = std::max({c.out_offset + spill_keep(), c.traced});
            if (keep < c.out.size()) {
                c.spill->append(std::string_view(c.out).substr(keep));
                c.out.resize(keep);
                c.out.shrink_to_fit();  // the budget it grew to goes back to the system, not only out of use
            }
            for (const auto& frame : c.backlog) c.spill->append(frame);
            c.backlog.clear();
            c.backlog_bytes = 0;
            memory_freed_ = true;  // and the heap is trimmed within a second (give_memory_back)
            log_spilling(c, "is not reading: what it is sent", c.spill->directory());
        }
        c.spill->append(c.tail);
        c.tail.clear();
        if (c.tail.capacity() > kKeptBufferBytes) c.tail.shrink_to_fit();
    } catch (const SpillError& e) {
        spill_failed(c, e.what());
        return true;
    }
    return held_for(c) <= options_.client_budget;
}

std::optional<std::uint64_t> Gateway::park(Connection& c, std::string_view frame) {
    if (!c.spill_failed.empty()) return std::nullopt;
    try {
        if (!c.parked) {
            c.parked = std::make_unique<SpillFile>(spill_budget_);
            log_spilling(c, "is not advancing: what time management holds for it", c.parked->directory());
        }
        return c.parked->append(frame);
    } catch (const SpillError& e) {
        spill_failed(c, e.what());
        return std::nullopt;
    }
}

std::string Gateway::unpark(Connection& c, std::uint64_t ticket, std::uint32_t size, bool keep) {
    std::string frame;
    if (!c.parked || !c.spill_failed.empty()) return frame;  // dropped at the end of the turn
    try {
        c.parked->read_at(ticket, size, frame);
        if (!keep) c.parked->release(size);
    } catch (const SpillError& e) {
        spill_failed(c, e.what());
        frame.clear();
    }
    return frame;
}

void Gateway::log_spilling(const Connection& c, const char* what, const std::string& directory) {
    log(c.peer + (c.federation ? " (federate " + std::to_string(c.federate) + " of '" + federation_name(c) + "')" : "") +
        " " + what + " beyond " + std::to_string(options_.client_budget) + " bytes is spilled to " + directory +
        " until it catches up (docs/robustness.md)");
}

void Gateway::spill_failed(Connection& c, const std::string& why) {
    if (!c.spill_failed.empty()) return;
    c.spill_failed = why;
    spill_failed_.push_back(c.fd);
}

void Gateway::drop_failed_spills() {
    std::vector<int> failed;
    failed.swap(spill_failed_);
    for (int fd : failed) {
        auto it = connections_.find(fd);
        if (it != connections_.end())
            close(fd, "not reading, and its backlog could not be spilled: " + it->second->spill_failed);
    }
}

void Gateway::give_memory_back() {
    const auto now = Clock::now();
    if (now - memory_given_back_at_ < std::chrono::seconds(1)) return;
    memory_freed_ = false;
    memory_given_back_at_ = now;
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
}

void Gateway::pause_if_over_budget(Connection& producer) {
    if (over_budget_ < 0) return;
    // Give the consumer's kernel buffer its chance first: pausing a producer whose consumer takes everything
    // at once would cost it a loop turn (up to 250 ms) per message.
    auto consumer = connections_.find(over_budget_);
    if (consumer != connections_.end()) flush(*consumer->second);
    consumer = connections_.find(over_budget_);
    if (consumer != connections_.end() && held_for(*consumer->second) > options_.client_budget)
        pause(producer, *consumer->second);
}

void Gateway::pause(Connection& producer, const Connection& consumer) {
    // A client over its budget with messages only its own requests release (a time advance) is not held
    // back from sending them; one whose output queue alone is over it is (it asks more than it reads).
    if (&producer == &consumer && producer.unsent() <= options_.client_budget) return;
    // Two clients holding each other back (each over its budget with the other's messages) would wait for
    // ever: the one that closes the circle is not paused and its consumer goes over budget instead.
    for (int fd = consumer.fd, steps = 0; steps <= static_cast<int>(paused_.size()); ++steps) {
        if (fd == producer.fd && &producer != &consumer) return;
        auto it = connections_.find(fd);
        if (it == connections_.end() || !it->second->paused) break;
        fd = it->second->blocked_by;
    }
    producer.paused = true;
    producer.blocked_by = consumer.fd;
    producer.paused_since = producer.keepalive_at = Clock::now();
    producer.pause_logged = false;
    paused_.push_back(producer.fd);
    update_events(producer);
}

void Gateway::update_events(Connection& c) {
    // A TLS write waiting for a read waits on EPOLLIN (which a paused connection still needs then), not on
    // EPOLLOUT, which would fire at once.
    const bool in = !c.paused || c.write_wants_read;
    const bool out = (c.write_armed && !c.write_wants_read) || c.read_wants_write;
    loop_.modify(c.fd, (in ? static_cast<std::uint32_t>(EPOLLIN) : 0u) | (out ? static_cast<std::uint32_t>(EPOLLOUT) : 0u));
}

// Each turn of the loop while connections are paused: resumes those whose consumer is below half its
// budget (or gone), sends the others a Pong now and then (their clients see the gateway alive while their
// sends wait) and logs a pause that lasts (drop_stalled_readers drops a consumer that stopped reading).
void Gateway::service_paused() {
    const auto now = Clock::now();
    std::vector<int> paused;
    paused.swap(paused_);
    for (int fd : paused) {
        auto it = connections_.find(fd);
        if (it == connections_.end()) continue;
        Connection& p = *it->second;
        auto blocker = connections_.find(p.blocked_by);
        // One that has stopped reading since is spilled (then p goes on).
        if (blocker != connections_.end() && !blocker->second->spill && stopped_reading(*blocker->second))
            spill(*blocker->second);
        if (blocker != connections_.end() && held_for(*blocker->second) > options_.client_budget / 2) {
            Connection& c = *blocker->second;
            if (!p.pause_logged && now - p.paused_since > std::chrono::seconds(10)) {
                p.pause_logged = true;
                log("holding back " + p.peer + " for 10 s: " + c.peer + " holds " + std::to_string(held_for(c)) +
                    " bytes for it (budget " + std::to_string(options_.client_budget) + "; docs/robustness.md)");
            }
            if (now - p.keepalive_at > std::chrono::seconds(1)) {
                p.keepalive_at = now;
                wire::encode(output(p), wire::Pong{0});
                mark_dirty(p);
            }
            paused_.push_back(fd);
            continue;
        }
        p.paused = false;
        p.blocked_by = -1;
        p.partial_since = now;
        update_events(p);
        serve_frames(p);  // what it had already sent; may pause it again
    }
    flush_dirty();
}

// Drops the clients that hold more than half their budget and have taken nothing for stall_timeout_s, whether
// or not a producer waits for them (it may have sent everything already); their producers resume next turn.
void Gateway::drop_stalled_readers() {
    if (options_.stall_timeout_s <= 0) return;
    const auto now = Clock::now();
    std::vector<std::pair<int, std::string>> stalled;
    for (const auto& [fd, c] : connections_) {
        const double idle = std::chrono::duration<double>(now - c->progress_at).count();
        // One that spills is paused, not dead (keepalive tells): dropped when its spill fails, unless what
        // time management holds for it keeps it over budget.
        const std::size_t time_held = c->federation ? c->federation->federation.held_bytes(c->federate) : 0;
        if (c->spill && time_held <= options_.client_budget / 2) continue;
        if (c->write_armed && idle > options_.stall_timeout_s && held_for(*c) > options_.client_budget / 2)
            stalled.emplace_back(fd, "not reading: " + std::to_string(c->unsent()) +
                                         " bytes queued, none taken for " + std::to_string(static_cast<int>(idle)) +
                                         " s (budget " + std::to_string(options_.client_budget) + ")");
    }
    for (const auto& [fd, why] : stalled) close(fd, why);
}

void Gateway::drop_stale_partials() {
    const auto now = Clock::now();
    const auto limit = std::chrono::duration<double>(options_.partial_frame_timeout_s);
    std::vector<std::pair<int, const char*>> stale;
    for (const auto& [fd, c] : connections_) {
        // A paused connection's unread frames wait for the gateway, not for the client.
        if (!c->paused && !c->in.empty() && now - c->partial_since > limit)
            stale.emplace_back(fd, "incomplete frame for too long");
        else if (!c->greeted && now - c->accepted_at > limit)  // connected, and silent since
            stale.emplace_back(fd, c->ssl && !SSL_is_init_finished(c->ssl.get())
                                       ? "no TLS handshake within the frame timeout"
                                       : "no handshake within the frame timeout");
    }
    for (const auto& [fd, why] : stale) close(fd, why);
}

}  // namespace hlacore
