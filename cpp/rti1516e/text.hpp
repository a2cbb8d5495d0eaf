// Text across the IEEE 1516-2010 API (std::wstring) and the core (UTF-8): types.cpp's codec, also used by the
// Federate Protocol's server (cpp/fedpro), which speaks UTF-8 on its wire.
#pragma once

#include <string>

namespace hlacore::rti1516e {

// RTIinternalError for a character that is not a Unicode scalar value.
std::string utf8(std::wstring const& text);
// Bytes that are not UTF-8 are taken as Latin-1.
std::wstring wide(std::string const& text);

}  // namespace hlacore::rti1516e
