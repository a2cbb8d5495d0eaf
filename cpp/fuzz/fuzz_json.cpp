// libFuzzer target for the JSON reader (rti/wire/json_value.hpp) the IEEE 1516-2010 C++ API reads the
// gateway's status report with: arbitrary bytes as a document.
//
// The only exception allowed out of parse_json is JsonError. A document that parses has the shape it says:
// strings only where the kind is String, members only in objects, items only in arrays.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "rti/wire/json_value.hpp"

namespace {
void check(bool ok) {
    if (!ok) std::abort();
}

void check_value(const hlacore::JsonValue& v, int depth) {
    using Kind = hlacore::JsonValue::Kind;
    check(depth <= hlacore::kMaxJsonDepth + 1);
    check(v.kind == Kind::Array || v.items.empty());
    check(v.kind == Kind::Object || v.members.empty());
    check(v.kind == Kind::String || v.text.empty());
    for (const auto& item : v.items) check_value(item, depth + 1);
    for (const auto& [name, member] : v.members) {
        check(v.find(name) != nullptr);
        check_value(member, depth + 1);
    }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        check_value(hlacore::parse_json(std::string_view(reinterpret_cast<const char*>(data), size)), 0);
    } catch (const hlacore::JsonError&) {
    }
    return 0;
}
