// What one end of a connection has read and not used yet: one block that the socket is read into directly,
// and that a large frame reserves whole as soon as its header is in (one allocation, no copy as it grows:
// growing a string by doubling copied a 16 MiB camera frame four times and mapped fresh pages for each).
// The gateway may share the block (share()) to write a large value on from where it was read; a shared
// block is not written again: the next read goes to the spare block (the one shared before, once nobody
// else holds it), so that a stream of camera frames alternates between two blocks. A federate shares it the
// same way with the large values it decodes (wire::Value), until they are delivered.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string_view>

#include "rti/wire/codec.hpp"

namespace hlacore::wire {

class ReadBuffer {
public:
    // Read size when no frame says more: one socket read of small frames.
    static constexpr std::size_t kChunk = 65536;

    std::string_view unread() const { return {data_.get() + begin_, end_ - begin_}; }
    bool empty() const { return begin_ == end_; }
    std::size_t capacity() const { return capacity_; }

    // How many bytes the next read should ask for: the rest of the frame under way when it is larger than a
    // chunk and within `max_frame_bytes` (a bigger length is refused when the frame is decoded), else a chunk.
    // Exactly the rest, even when that is less than a chunk: the frame's block was reserved to its size, and
    // a chunk more than fits would move all of it to a bigger one.
    std::size_t wanted(std::uint32_t max_frame_bytes) const {
        const std::size_t pending = end_ - begin_;
        if (pending < 4) return kChunk;
        std::uint32_t length = 0;
        std::memcpy(&length, data_.get() + begin_, 4);
        if (length > max_frame_bytes) return kChunk;
        const std::size_t frame = 4 + static_cast<std::size_t>(length);
        return frame > pending && frame > kChunk ? frame - pending : kChunk;
    }
    // Whether the first unread frame is whole and larger than a chunk. Its block was reserved for it, so reading
    // on would move all of it to make room: a plain socket's reader decodes it first. (A TLS reader reads on
    // while its session holds decrypted bytes, which poll() would not report.)
    bool holds_large_frame() const {
        const std::size_t pending = end_ - begin_;
        if (pending <= kChunk) return false;
        std::uint32_t length = 0;
        std::memcpy(&length, data_.get() + begin_, 4);
        const std::size_t frame = 4 + static_cast<std::size_t>(length);
        return frame > kChunk && frame <= pending;
    }
    // Room for `n` more bytes at the end; read into it, then commit() what was read.
    char* room(std::size_t n) {
        const std::size_t pending = end_ - begin_;
        const bool shared = data_.use_count() > 1;  // its bytes are still being written or read elsewhere
        // A block that another thread let go of (a delivered value) is written only after that thread's reads.
        std::atomic_thread_fence(std::memory_order_acquire);
        if (!shared && capacity_ - end_ >= n) return data_.get() + end_;
        if (!shared && capacity_ >= pending + n) {  // what was used makes the room
            std::memmove(data_.get(), data_.get() + begin_, pending);
        } else {
            // Exactly what is asked for a frame larger than a chunk (it reserves its whole length once);
            // doubled for small frames, so that reads of them stay amortized.
            std::size_t size = n > kChunk ? pending + n : std::max(pending + n, shared ? kChunk : 2 * capacity_);
            std::shared_ptr<char[]> block;
            if (spare_.use_count() == 1 && spare_capacity_ >= size) {
                block.swap(spare_);
                size = spare_capacity_;
            } else {
                block.reset(new char[size]);
            }
            if (pending) std::memcpy(block.get(), data_.get() + begin_, pending);
            if (shared) {
                spare_ = std::move(data_);
                spare_capacity_ = capacity_;
            }
            data_ = std::move(block);
            capacity_ = size;
        }
        begin_ = 0;
        end_ = pending;
        return data_.get() + end_;
    }
    void commit(std::size_t n) { end_ += n; }
    // The first `n` unread bytes were used (whole frames).
    void consume(std::size_t n) {
        begin_ += n;
        if (begin_ == end_) begin_ = end_ = 0;
    }
    // Gives the block back when nothing is unread and it is larger than `keep`.
    void release_above(std::size_t keep) {
        if (spare_capacity_ > keep) {
            spare_.reset();
            spare_capacity_ = 0;
        }
        if (begin_ == end_ && capacity_ > keep) {
            data_.reset();
            capacity_ = begin_ = end_ = 0;
        }
    }
    void clear() { begin_ = end_ = 0; }
    // The block, for bytes viewed in it to outlive their use here (see room()).
    std::shared_ptr<const char[]> share() const { return data_; }

private:
    std::shared_ptr<char[]> data_;
    std::shared_ptr<char[]> spare_;
    std::size_t spare_capacity_ = 0;
    std::size_t capacity_ = 0;
    std::size_t begin_ = 0;
    std::size_t end_ = 0;
};

}  // namespace hlacore::wire
