// CERTI's federate protocol: the layouts as data, each message written and read by walking its layout.
#include "certi/protocol.hpp"

#include <cstring>
#include <initializer_list>
#include <limits>

namespace hlacore::certi {

namespace {

struct Layout {
    const char* name;
    std::initializer_list<Field> fields;
};

using namespace fields;
#define HLACORE_CERTI_LAYOUT(name, ...) {#name, {__VA_ARGS__}},
const Layout kLayouts[] = {HLACORE_CERTI_MESSAGES(HLACORE_CERTI_LAYOUT)};
#undef HLACORE_CERTI_LAYOUT

#define HLACORE_CERTI_EXCEPTION_NAME(name) #name,
const char* const kExceptionNames[] = {HLACORE_CERTI_EXCEPTIONS(HLACORE_CERTI_EXCEPTION_NAME)};
#undef HLACORE_CERTI_EXCEPTION_NAME

const Layout* layout_of(Type type) {
    const auto code = static_cast<std::int32_t>(type);
    if (code < 1 || code >= static_cast<std::int32_t>(Type::LAST)) return nullptr;
    return &kLayouts[code - 1];
}

// Numbers in either byte order.
class Writer {
public:
    explicit Writer(bool big_endian) : big_(big_endian) { out_.assign(kFrameHeader, '\0'); }
    void u8(std::uint8_t v) { out_.push_back(static_cast<char>(v)); }
    void boolean(bool v) { u8(v ? 1 : 0); }
    void u16(std::uint16_t v) { number(v, 2); }
    void u32(std::uint32_t v) { number(v, 4); }
    void i32(std::int32_t v) { number(static_cast<std::uint32_t>(v), 4); }
    void u64(std::uint64_t v) { number(v, 8); }
    void f64(double v) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, 8);
        u64(bits);
    }
    void bytes(const std::string& s) {
        if (s.size() > std::numeric_limits<std::int32_t>::max()) throw ProtocolError("a string or value beyond 2 GiB");
        u32(static_cast<std::uint32_t>(s.size()));
        out_ += s;
    }
    // The frame: its header filled in.
    std::string finish() {
        if (out_.size() > kMaxFrame)
            throw ProtocolError("a message of " + std::to_string(out_.size()) + " bytes, beyond the frame limit");
        out_[0] = big_ ? 1 : 0;
        put(&out_[1], out_.size(), 4);
        return std::move(out_);
    }

private:
    void put(char* at, std::uint64_t v, int size) const {
        for (int i = 0; i < size; ++i) at[big_ ? size - 1 - i : i] = static_cast<char>(v >> (8 * i));
    }
    void number(std::uint64_t v, int size) {
        char b[8];
        put(b, v, size);
        out_.append(b, static_cast<std::size_t>(size));
    }
    bool big_;
    std::string out_;
};

class Reader {
public:
    Reader(std::string_view in, bool big_endian) : in_(in), big_(big_endian) {}
    std::uint8_t u8() { return static_cast<std::uint8_t>(take(1)[0]); }
    bool boolean() { return u8() != 0; }
    std::uint16_t u16() { return static_cast<std::uint16_t>(number(2)); }
    std::uint32_t u32() { return static_cast<std::uint32_t>(number(4)); }
    std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
    std::uint64_t u64() { return number(8); }
    double f64() {
        const std::uint64_t bits = u64();
        double v;
        std::memcpy(&v, &bits, 8);
        return v;
    }
    std::string bytes() {
        const std::uint32_t length = u32();
        const std::string_view s = take(length);
        return std::string(s);
    }
    // A count of items of at least `item` bytes each, checked against what is left (no allocation beyond it).
    std::uint32_t count(std::size_t item) {
        const std::uint32_t n = u32();
        if (static_cast<std::uint64_t>(n) * item > in_.size() - at_)
            throw ProtocolError("a list of " + std::to_string(n) + " items at byte " + std::to_string(at_ + kFrameHeader - 4) +
                                " goes beyond the frame");
        return n;
    }
    std::size_t left() const { return in_.size() - at_; }

private:
    std::string_view take(std::size_t n) {
        if (n > in_.size() - at_)
            throw ProtocolError("truncated: " + std::to_string(n) + " bytes wanted at byte " +
                                std::to_string(at_ + kFrameHeader) + ", " + std::to_string(in_.size() - at_) + " left");
        const std::string_view s = in_.substr(at_, n);
        at_ += n;
        return s;
    }
    std::uint64_t number(int size) {
        const std::string_view b = take(static_cast<std::size_t>(size));
        std::uint64_t v = 0;
        for (int i = 0; i < size; ++i)
            v |= static_cast<std::uint64_t>(static_cast<std::uint8_t>(b[big_ ? size - 1 - i : i])) << (8 * i);
        return v;
    }
    std::string_view in_;
    std::size_t at_ = 0;
    bool big_;
};

void write_field(Writer& w, const Message& m, Field f) {
    switch (f) {
        case VersionMajor: w.u32(m.version_major); break;
        case VersionMinor: w.u32(m.version_minor); break;
        case FederationName: w.bytes(m.federation_name); break;
        case FedId: w.bytes(m.fed_id); break;
        case FederateName: w.bytes(m.federate_name); break;
        case Name: w.bytes(m.name); break;
        case Reason: w.bytes(m.restore_reason); break;
        case Federate: w.u32(m.federate); break;
        case ObjectClass: w.u32(m.object_class); break;
        case InteractionClass: w.u32(m.interaction_class); break;
        case Object: w.u32(m.object); break;
        case Attribute: w.u32(m.attribute); break;
        case Parameter: w.u32(m.parameter); break;
        case Space: w.u32(m.space); break;
        case Dimension: w.u32(m.dimension); break;
        case Region: w.u32(m.region); break;
        case ExtentCount: w.u32(m.extent_count); break;
        case ResignAction: w.u16(m.resign_action); break;
        case Transport: w.u8(m.transport); break;
        case Order: w.u8(m.order); break;
        case Flag: w.boolean(m.flag); break;
        case Lookahead: w.f64(m.lookahead); break;
        case MinTick: w.f64(m.min_tick); break;
        case MaxTick: w.f64(m.max_tick); break;
        case Handles:
            w.u32(static_cast<std::uint32_t>(m.handles.size()));
            for (std::uint32_t h : m.handles) w.u32(h);
            break;
        case Values:
            w.u32(static_cast<std::uint32_t>(m.values.size()));
            for (const std::string& v : m.values) w.bytes(v);
            break;
        case OptionalName:
            w.boolean(m.has_name);
            if (m.has_name) w.bytes(m.name);
            break;
        case OptionalRetraction:
            w.boolean(m.retraction.has_value());
            if (!m.retraction) break;
            [[fallthrough]];
        case Retraction: {
            const EventRetraction r = m.retraction.value_or(EventRetraction{});
            w.u32(r.federate);
            w.u64(r.serial);
            break;
        }
        case RtiVersion: w.u8(m.rti_version); break;
        case FederateType: w.bytes(m.federate_type); break;
        case OptionalMim:
        case OptionalTimeName: {
            const std::optional<std::string>& text = f == OptionalMim ? m.mim : m.time_name;
            w.boolean(text.has_value());
            if (text) w.bytes(*text);
            break;
        }
    }
}

void read_field(Reader& r, Message& m, Field f) {
    switch (f) {
        case VersionMajor: m.version_major = r.u32(); break;
        case VersionMinor: m.version_minor = r.u32(); break;
        case FederationName: m.federation_name = r.bytes(); break;
        case FedId: m.fed_id = r.bytes(); break;
        case FederateName: m.federate_name = r.bytes(); break;
        case Name: m.name = r.bytes(); break;
        case Reason: m.restore_reason = r.bytes(); break;
        case Federate: m.federate = r.u32(); break;
        case ObjectClass: m.object_class = r.u32(); break;
        case InteractionClass: m.interaction_class = r.u32(); break;
        case Object: m.object = r.u32(); break;
        case Attribute: m.attribute = r.u32(); break;
        case Parameter: m.parameter = r.u32(); break;
        case Space: m.space = r.u32(); break;
        case Dimension: m.dimension = r.u32(); break;
        case Region: m.region = r.u32(); break;
        case ExtentCount: m.extent_count = r.u32(); break;
        case ResignAction: m.resign_action = r.u16(); break;
        case Transport: m.transport = r.u8(); break;
        case Order: m.order = r.u8(); break;
        case Flag: m.flag = r.boolean(); break;
        case Lookahead: m.lookahead = r.f64(); break;
        case MinTick: m.min_tick = r.f64(); break;
        case MaxTick: m.max_tick = r.f64(); break;
        case Handles: {
            const std::uint32_t n = r.count(4);
            m.handles.resize(n);
            for (auto& h : m.handles) h = r.u32();
            break;
        }
        case Values: {
            const std::uint32_t n = r.count(4);
            m.values.resize(n);
            for (auto& v : m.values) v = r.bytes();
            break;
        }
        case OptionalName:
            m.has_name = r.boolean();
            if (m.has_name) m.name = r.bytes();
            break;
        case OptionalRetraction:
            if (!r.boolean()) break;
            [[fallthrough]];
        case Retraction: {
            EventRetraction e;
            e.federate = r.u32();
            e.serial = r.u64();
            m.retraction = e;
            break;
        }
        case RtiVersion: m.rti_version = r.u8(); break;
        case FederateType: m.federate_type = r.bytes(); break;
        case OptionalMim: if (r.boolean()) m.mim = r.bytes(); break;
        case OptionalTimeName: if (r.boolean()) m.time_name = r.bytes(); break;
    }
}

}  // namespace

const char* type_name(Type type) {
    const Layout* layout = layout_of(type);
    return layout ? layout->name : "an unknown type";
}

const char* exception_name(Exception code) {
    const auto c = static_cast<std::int32_t>(code);
    return c >= 1 && c < static_cast<std::int32_t>(Exception::Count) ? kExceptionNames[c - 1] : "";
}

Exception exception_named(std::string_view name) {
    for (std::int32_t c = 1; c < static_cast<std::int32_t>(Exception::Count); ++c)
        if (name == kExceptionNames[c - 1]) return static_cast<Exception>(c);
    return Exception::RTIinternalError;
}

std::string encode(const Message& m, bool big_endian) {
    const Layout* layout = layout_of(m.type);
    if (!layout) throw ProtocolError("no message type " + std::to_string(static_cast<std::int32_t>(m.type)));
    Writer w(big_endian);
    w.i32(static_cast<std::int32_t>(m.type));
    w.i32(static_cast<std::int32_t>(m.exception));
    if (m.exception != Exception::None) {
        w.bytes(m.reason);
    } else {
        w.boolean(m.date.has_value());
        if (m.date) w.f64(*m.date);
        w.boolean(m.label.has_value());
        if (m.label) w.bytes(*m.label);
        w.boolean(m.tag.has_value());
        if (m.tag) w.bytes(*m.tag);
    }
    for (Field f : layout->fields) write_field(w, m, f);
    return w.finish();
}

std::uint32_t frame_length(std::string_view header) {
    if (header.size() < kFrameHeader) throw ProtocolError("a frame header of " + std::to_string(header.size()) + " bytes");
    const auto order = static_cast<std::uint8_t>(header[0]);
    if (order > 1) throw ProtocolError("byte-order flag " + std::to_string(order) + " (0 or 1)");
    const std::uint32_t length = Reader(header.substr(1, 4), order == 1).u32();
    if (length < kFrameHeader + 8 || length > kMaxFrame)
        throw ProtocolError("a frame length of " + std::to_string(length) + " bytes (13 to " + std::to_string(kMaxFrame) + ")");
    return length;
}

Message decode(std::string_view frame, bool* big_endian) {
    const std::uint32_t length = frame_length(frame);
    if (length != frame.size())
        throw ProtocolError("a frame of " + std::to_string(frame.size()) + " bytes says " + std::to_string(length));
    const bool big = frame[0] == 1;
    if (big_endian) *big_endian = big;
    Reader r(frame.substr(kFrameHeader), big);
    Message m;
    m.type = static_cast<Type>(r.i32());
    const Layout* layout = layout_of(m.type);
    if (!layout) throw ProtocolError("unknown message type " + std::to_string(static_cast<std::int32_t>(m.type)));
    const std::int32_t exception = r.i32();
    if (exception < 0 || exception >= static_cast<std::int32_t>(Exception::Count))
        throw ProtocolError("unknown exception code " + std::to_string(exception) + " in " + layout->name);
    m.exception = static_cast<Exception>(exception);
    if (m.exception != Exception::None) {
        m.reason = r.bytes();
    } else {
        if (r.boolean()) m.date = r.f64();
        if (r.boolean()) m.label = r.bytes();
        if (r.boolean()) m.tag = r.bytes();
    }
    try {
        for (Field f : layout->fields) read_field(r, m, f);
    } catch (const ProtocolError& e) {
        throw ProtocolError(std::string(layout->name) + ": " + e.what());
    }
    // Bytes after the last field are ignored, as CERTI's own readers ignore them: JCERTI's IEEE 1516-2010
    // update writes a stray count there. The frame's length keeps the stream in step.
    return m;
}

}  // namespace hlacore::certi
