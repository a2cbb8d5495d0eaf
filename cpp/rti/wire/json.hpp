// JSON writing: the gateway's status report (server/status.cpp) and the recording (server/recorder.cpp),
// which writes a wire message as a JSON object, its field names from HLACORE_FIELDS.
// Encodings: integers and bools as JSON numbers and booleans, a double as the shortest number that reads
// back as the same double (infinities and NaN as null), an absent time as null,
// handle lists as arrays, a text that is valid UTF-8 as a JSON string and any other byte string as
// {"base64": "..."}, handle-value pairs as [handle, "base64 of the value"], nested records as objects.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "rti/wire/codec.hpp"

namespace hlacore {

void json_string(std::string& out, std::string_view s);  // quoted and escaped, bytes as they are
void json_number(std::string& out, double v);            // infinities and NaN as null
void json_base64(std::string& out, std::string_view bytes);  // its base64 as a JSON string
void json_text(std::string& out, std::string_view text);     // a JSON string, or {"base64": ...} if not UTF-8

// A JSON array of `items`, each written by `write(item)`.
template <class Items, class Write>
void json_array(std::string& out, const Items& items, Write&& write) {
    out += '[';
    bool first = true;
    for (const auto& item : items) {
        if (!first) out += ',';
        first = false;
        write(item);
    }
    out += ']';
}

namespace wire {

class JsonWriter {
public:
    JsonWriter(std::string& out, const char* names) : out_(out), names_(names) {}

    template <class... T>
    void operator()(const T&... values) { (field(values), ...); }

    static void put(std::string& out, bool v) { out += v ? "true" : "false"; }
    template <class T, std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, bool>, int> = 0>
    static void put(std::string& out, T v) {
        char buf[24];
        out.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
    }
    template <class T, std::enable_if_t<std::is_enum_v<T>, int> = 0>
    static void put(std::string& out, T v) { put(out, static_cast<std::underlying_type_t<T>>(v)); }
    static void put(std::string& out, double v) { json_number(out, v); }
    static void put(std::string& out, const std::string& s) { json_text(out, s); }
    static void put(std::string& out, const OptionalTime& t) {
        if (t) json_number(out, *t);
        else out += "null";
    }
    template <class V, std::enable_if_t<std::is_same_v<V, Value> || std::is_same_v<V, std::string_view>, int> = 0>
    static void put(std::string& out, const std::pair<std::uint32_t, V>& hv) {  // HandleValue(View)
        out += '[';
        put(out, hv.first);
        out += ',';
        json_base64(out, hv.second);
        out += ']';
    }
    template <class T>
    static void put(std::string& out, const std::vector<T>& items) {
        out += '[';
        for (std::size_t i = 0; i < items.size(); ++i) {
            if (i) out += ',';
            put(out, items[i]);
        }
        out += ']';
    }
    template <class T>
    static void put(std::string& out, const Boxed<T>& boxed) { put(out, *boxed); }
    template <class T, class = decltype(T::kFieldNames)>
    static void put(std::string& out, const T& record) {
        out += '{';
        JsonWriter w(out, T::kFieldNames);
        record.fields(w);
        out += '}';
    }

private:
    template <class T>
    void field(const T& value) {
        std::string_view names(names_);
        const auto end = names.find(',');
        const std::string_view name = names.substr(0, end);
        names_ = end == std::string_view::npos ? names_ + names.size() : names_ + end + 1;
        if (!first_) out_ += ',';
        first_ = false;
        out_ += '"';
        out_.append(trim(name));
        out_ += "\":";
        put(out_, value);
    }
    static std::string_view trim(std::string_view s) {
        while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
        while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
        return s;
    }

    std::string& out_;
    const char* names_;
    bool first_ = true;
};

// `message`'s fields as a JSON object.
template <class M>
void to_json(std::string& out, const M& message) {
    JsonWriter::put(out, message);
}

}  // namespace wire
}  // namespace hlacore
