// Minimal JSON writing for the gateway's status report.
#pragma once

#include <string>

namespace hlacore {

void json_string(std::string& out, const std::string& s);
void json_number(std::string& out, double v);  // infinities and NaN as null

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

}  // namespace hlacore
