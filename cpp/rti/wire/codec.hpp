// The bounds-checked binary codec of the wire protocol's messages (messages.hpp): frames, their encoding and
// decoding; the runtime half (names, framing) is messages.cpp.
#pragma once

#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

#include "rti/wire/messages.hpp"

#if !defined(__BYTE_ORDER__) || __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "the codec assumes a little-endian host"
#endif

namespace hlacore::wire {

// ---- the codec ----
//
// Field encodings (little-endian): integers fixed width, bool one byte (0/1), double as its IEEE bits,
// string u32 length + bytes, vector u32 count + elements, optional<double> one byte flag + double, a nested
// record (a struct with HLACORE_FIELDS) its fields in order, a Boxed<T> its T.
// Decoding never reads past the frame, and a count can never ask for more elements than the
// remaining bytes could hold, so a length field cannot make us allocate unbounded memory.

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
    void put(std::string_view s) {
        put(static_cast<std::uint32_t>(s.size()));
        out_.append(s.data(), s.size());
    }
    void put(const Value& v) { put(v.view()); }
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
    template <class T>
    void put(const T* pointed) {  // HandleValueRefs
        put(*pointed);
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

// Values from this size on are written from where they are rather than copied into an output buffer: by a
// federate that sends them and by the gateway to each receiver (splices.hpp); and a
// federate decodes them as views into the block it read them into (Frame::block).
constexpr std::size_t kSplicedValueBytes = 256u << 10;

class Reader {
public:
    // With `block`, the one `data` lies in, large values are decoded as views into it (see Value).
    Reader(std::string_view data, MessageType type, const std::shared_ptr<const char[]>* block = nullptr)
        : p_(data.data()), end_(data.data() + data.size()), type_(type), block_(block) {}

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
    void get(Value& v) {
        std::string_view bytes;
        get(bytes);
        if (block_ && bytes.size() >= kSplicedValueBytes)
            v = Value(*block_, bytes);
        else
            v.assign(bytes);
    }
    void get(std::string_view& s) {  // a view into the frame, valid while it is
        std::uint32_t n = 0;
        get(n);
        need(n);
        s = std::string_view(p_, n);
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
    const std::shared_ptr<const char[]>* block_;
};

// The frame's length field for `m` (type + payload: what the frame limit counts), without encoding it.
template <class M>
std::size_t frame_length(const M& m) {
    ByteCount count;
    BasicWriter<ByteCount> w(count);
    m.fields(w);
    return 2 + count.bytes;
}

// Writes into room already made for all of it: no capacity check per field, where std::string::append's
// (out of line) was a tenth of a sender's CPU per small update.
struct RawOutput {
    char* at;
    void append(const char* data, std::size_t n) {
        std::memcpy(at, data, n);
        at += n;
    }
    void append(const std::string& s) { append(s.data(), s.size()); }
};
// Frames up to this size are written into room made first (zero-filled, which a larger one would notice).
constexpr std::size_t kEncodedInPlaceBytes = 4096;

// Appends one complete frame holding `m`, whose frame_length() is `length`, to `out`.
template <class M>
void encode(std::string& out, const M& m, std::size_t length) {
    const std::size_t start = out.size();
    const auto type = static_cast<std::uint16_t>(M::kType);
    if (length <= kEncodedInPlaceBytes) {
        out.resize(start + 4 + length);
        RawOutput raw{&out[start]};
        const auto length32 = static_cast<std::uint32_t>(length);
        raw.append(reinterpret_cast<const char*>(&length32), 4);
        raw.append(reinterpret_cast<const char*>(&type), 2);
        BasicWriter<RawOutput> w(raw);
        m.fields(w);
        return;
    }
    out.append(kHeaderBytes, '\0');
    Writer w(out);
    m.fields(w);
    const auto written = static_cast<std::uint32_t>(out.size() - start - 4);
    std::memcpy(&out[start], &written, 4);
    std::memcpy(&out[start + 4], &type, 2);
}
// Appends one complete frame holding `m` to `out`.
template <class M>
void encode(std::string& out, const M& m) {
    encode(out, m, frame_length(m));
}
void encode(std::string& out, const Message& m);

inline const HandleValueView& value_of(const HandleValueView& value) { return value; }
inline const HandleValueView& value_of(const HandleValueView* value) { return *value; }
// Whether an update's or interaction's values (views, or the gateway's pointers to them) hold such a value.
template <class Values>
bool has_spliced_value(const Values& values) {
    for (const auto& value : values)
        if (value_of(value).second.size() >= kSplicedValueBytes) return true;
    return false;
}

// Appends one complete frame holding `m` to `out`, which only appends (like ByteCount): its header is
// written first, from frame_length(). wire::SplicingOutput (splices.hpp) is one.
template <class Out, class M>
void encode_to(Out& out, const M& m) {
    const auto length = static_cast<std::uint32_t>(frame_length(m));
    const auto type = static_cast<std::uint16_t>(M::kType);
    out.append(reinterpret_cast<const char*>(&length), 4);
    out.append(reinterpret_cast<const char*>(&type), 2);
    BasicWriter<Out> w(out);
    m.fields(w);
}

// An encoded frame that several receivers' queues hold (the gateway's timestamp-ordered queues): one string,
// not a copy each.
using SharedFrame = std::shared_ptr<std::string>;

struct Frame {
    MessageType type = MessageType::Invalid;
    std::string_view payload;
    // The block the payload lies in, when large values may be decoded as views into it (a Value keeps it).
    const std::shared_ptr<const char[]>* block = nullptr;
};

// Looks for one complete frame at the start of `buffer`. Returns the bytes it spans, or 0 if more bytes
// are needed. Throws WireError when the header is impossible (length too short or above max_bytes).
std::size_t next_frame(std::string_view buffer, Frame& frame, std::uint32_t max_bytes = kMaxFrameBytes);

// Decodes a frame of M's type into m, or as M (a view type such as UpdateAttributesView included).
template <class M>
void decode_fields(const Frame& frame, M& m) {
    Reader r(frame.payload, frame.type, frame.block);
    m.fields(r);
    if (r.remaining() != 0) r.fail("trailing bytes");
}
template <class M>
M decode_as(const Frame& frame) {
    M m;
    decode_fields(frame, m);
    return m;
}

// Decodes a frame into the message of its type, in `into`, where it stays: a reflection is not moved twice
// more on its way to the callback queue; after a WireError, `into` holds what was decoded so far. Throws
// WireError on an unknown type, a truncated field or trailing bytes. A template so that only the files that
// decode compile the switch.
template <class Variant = Message>
void decode(const Frame& frame, Variant& into) {
    switch (frame.type) {
#define HLACORE_X(name)                                      \
    case MessageType::name:                                  \
        decode_fields(frame, into.template emplace<name>()); \
        return;
        HLACORE_MESSAGES(HLACORE_X)
#undef HLACORE_X
        default: throw WireError("unknown message type " + std::to_string(static_cast<unsigned>(frame.type)));
    }
}
template <class Variant = Message>
Variant decode(const Frame& frame) {
    Variant m;
    decode(frame, m);
    return m;
}
}  // namespace hlacore::wire
