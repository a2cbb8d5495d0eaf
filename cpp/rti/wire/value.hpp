// The bytes of one attribute or parameter value: its own string, or, for a large value a federate received,
// a view into the block it was read into, which the value keeps alive. The receiver then copies a camera
// frame once, into what it hands its caller (a Python bytes, or the HLA 1.3 pair set's pointer reads it
// there), instead of first into a string of its own.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

namespace hlacore::wire {

class Value {
public:
    Value() = default;
    Value(std::string bytes) : owned_(std::move(bytes)) {}  // NOLINT: implicit, values are built from strings
    Value(std::string_view bytes) : owned_(bytes) {}        // NOLINT
    Value(const char* bytes) : owned_(bytes) {}             // NOLINT
    // `bytes` inside `block`, kept alive as long as this value (or a copy of it) is.
    Value(std::shared_ptr<const char[]> block, std::string_view bytes) : block_(std::move(block)), view_(bytes) {}

    // Its own copy of `bytes` (no block).
    void assign(std::string_view bytes) {
        owned_.assign(bytes.data(), bytes.size());
        block_.reset();
        view_ = {};
    }

    std::string_view view() const { return block_ ? view_ : std::string_view(owned_); }
    operator std::string_view() const { return view(); }  // NOLINT: a value reads as its bytes
    const char* data() const { return view().data(); }
    std::size_t size() const { return view().size(); }
    bool empty() const { return size() == 0; }
    // Whether the bytes are a view into a received block (for tests).
    bool in_block() const { return block_ != nullptr; }

    friend bool operator==(const Value& a, const Value& b) { return a.view() == b.view(); }
    friend bool operator!=(const Value& a, const Value& b) { return !(a == b); }

private:
    std::string owned_;
    std::shared_ptr<const char[]> block_;
    std::string_view view_;
};

}  // namespace hlacore::wire
