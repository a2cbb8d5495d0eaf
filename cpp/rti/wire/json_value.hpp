// JSON reading, for what a federate learns from the gateway's status report (client's query_status; the
// IEEE 1516-2010 C++ API's federation and save/restore status services). A value tree: objects keep their
// members in order, numbers are doubles. Text that is not JSON, or nests deeper than kMaxJsonDepth, raises
// JsonError naming the offset. cpp/fuzz/fuzz_json.cpp fuzzes parse_json.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hlacore {

class JsonError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

constexpr int kMaxJsonDepth = 64;

struct JsonValue {
    enum class Kind { Null, Bool, Number, String, Array, Object };
    Kind kind = Kind::Null;
    bool boolean = false;
    double number = 0;
    std::string text;
    std::vector<JsonValue> items;                              // an array's
    std::vector<std::pair<std::string, JsonValue>> members;    // an object's

    // An object's member, or null when it has none of that name (or is not an object).
    const JsonValue* find(std::string_view key) const;
    // An object's member; JsonError when it is missing.
    const JsonValue& at(std::string_view key) const;
};

JsonValue parse_json(std::string_view text);

}  // namespace hlacore
