// Minimal JSON writing for the gateway's status report.
#pragma once

#include <string>

namespace hlacore {

void json_string(std::string& out, const std::string& s);
void json_number(std::string& out, double v);  // infinities and NaN as null

}  // namespace hlacore
