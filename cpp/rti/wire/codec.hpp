// Framing and the bounds-checked binary codec for wire::Message. No sockets here.
//
// Field encodings (little-endian): integers fixed width, bool one byte (0/1), double as its IEEE bits,
// string u32 length + bytes, vector u32 count + elements, optional<double> one byte flag + double, a nested
// record (a struct with HLACORE_FIELDS) its fields in order, a Boxed<T> its T.
// Decoding never reads past the frame, and a count can never ask for more elements than the
// remaining bytes could hold, so a length field cannot make us allocate unbounded memory.
#pragma once

#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "rti/wire/messages.hpp"

#if !defined(__BYTE_ORDER__) || __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "the codec assumes a little-endian host"
#endif

namespace hlacore::wire {

class WireError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

constexpr std::size_t kHeaderBytes = 6;  // u32 length + u16 type

// Appends fields to Out: a std::string, or a ByteCount to learn an encoding's size without making it.
template <class Out>
class BasicWriter {
public:
    explicit BasicWriter(Out& out) : out_(out) {}

    template <class... T>
    void operator()(const T&... values) { (put(values), ...); }

    void put(bool v) { put(static_cast<std::uint8_t>(v ? 1 : 0)); }
    void put(std::uint8_t v) { raw(&v, 1); }
    void put(std::uint16_t v) { raw(&v, 2); }
    void put(std::uint32_t v) { raw(&v, 4); }
    void put(std::uint64_t v) { raw(&v, 8); }
    void put(double v) { raw(&v, 8); }
    void put(const std::string& s) {
        put(static_cast<std::uint32_t>(s.size()));
        out_.append(s);
    }
    void put(const OptionalTime& t) {
        put(t.has_value());
        if (t) put(*t);
    }
    template <class T>
    void put(const std::vector<T>& items) {
        put(static_cast<std::uint32_t>(items.size()));
        for (const auto& item : items) put(item);
    }
    template <class A, class B>
    void put(const std::pair<A, B>& p) {
        put(p.first);
        put(p.second);
    }
    template <class T, class = decltype(std::declval<const T&>().fields(std::declval<BasicWriter&>()))>
    void put(const T& record) {
        record.fields(*this);
    }
    template <class T>
    void put(const Boxed<T>& boxed) {
        put(*boxed);
    }

private:
    void raw(const void* p, std::size_t n) { out_.append(static_cast<const char*>(p), n); }
    Out& out_;
};

struct ByteCount {
    std::size_t bytes = 0;
    void append(const char*, std::size_t n) { bytes += n; }
    void append(const std::string& s) { bytes += s.size(); }
};

using Writer = BasicWriter<std::string>;

class Reader {
public:
    Reader(std::string_view data, MessageType type) : p_(data.data()), end_(data.data() + data.size()), type_(type) {}

    template <class... T>
    void operator()(T&... values) { (get(values), ...); }

    void get(bool& v) {
        std::uint8_t b = 0;
        get(b);
        if (b > 1) fail("bad boolean");
        v = b == 1;
    }
    void get(std::uint8_t& v) { raw(&v, 1); }
    void get(std::uint16_t& v) { raw(&v, 2); }
    void get(std::uint32_t& v) { raw(&v, 4); }
    void get(std::uint64_t& v) { raw(&v, 8); }
    void get(double& v) { raw(&v, 8); }
    void get(std::string& s) {
        std::uint32_t n = 0;
        get(n);
        need(n);
        s.assign(p_, n);
        p_ += n;
    }
    void get(OptionalTime& t) {
        bool present = false;
        get(present);
        if (present) {
            double v = 0;
            get(v);
            t = v;
        } else {
            t.reset();
        }
    }
    template <class T>
    void get(std::vector<T>& items) {
        std::uint32_t n = 0;
        get(n);
        // Every element takes at least 4 bytes (all our element types), which bounds the allocation.
        if (n > remaining() / 4) fail("element count exceeds frame");
        items.clear();
        items.resize(n);
        for (auto& item : items) get(item);
    }
    template <class A, class B>
    void get(std::pair<A, B>& p) {
        get(p.first);
        get(p.second);
    }
    template <class T, class = decltype(std::declval<T&>().fields(std::declval<Reader&>()))>
    void get(T& record) {
        record.fields(*this);
    }
    template <class T>
    void get(Boxed<T>& boxed) {
        get(boxed.edit());
    }

    std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }
    [[noreturn]] void fail(const char* what) const;

private:
    void need(std::size_t n) const {
        if (n > remaining()) fail("truncated field");
    }
    void raw(void* p, std::size_t n) {
        need(n);
        std::memcpy(p, p_, n);
        p_ += n;
    }
    const char* p_;
    const char* end_;
    MessageType type_;
};

// Appends one complete frame holding `m` to `out`.
template <class M>
void encode(std::string& out, const M& m) {
    const std::size_t start = out.size();
    out.append(kHeaderBytes, '\0');
    Writer w(out);
    m.fields(w);
    const auto length = static_cast<std::uint32_t>(out.size() - start - 4);
    const auto type = static_cast<std::uint16_t>(M::kType);
    std::memcpy(&out[start], &length, 4);
    std::memcpy(&out[start + 4], &type, 2);
}
void encode(std::string& out, const Message& m);

// The frame's length field for `m` (type + payload: what the frame limit counts), without encoding it.
template <class M>
std::size_t frame_length(const M& m) {
    ByteCount count;
    BasicWriter<ByteCount> w(count);
    m.fields(w);
    return 2 + count.bytes;
}

struct Frame {
    MessageType type = MessageType::Invalid;
    std::string_view payload;
};

// Looks for one complete frame at the start of `buffer`. Returns the bytes it spans, or 0 if more bytes
// are needed. Throws WireError when the header is impossible (length too short or above max_bytes).
std::size_t next_frame(std::string_view buffer, Frame& frame, std::uint32_t max_bytes = kMaxFrameBytes);

// Decodes a frame's payload. Throws WireError on an unknown type, a truncated field or trailing bytes.
Message decode(const Frame& frame);

}  // namespace hlacore::wire
