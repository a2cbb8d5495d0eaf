// The enumerators of an append-only X-macro list whose position is the code on the wire
// (HLACORE_MESSAGES, HLACORE_EXCEPTIONS): `none` = 0, then each name of the list from 1, then Count;
// and their names: HLACORE_LIST_NAMES(LIST) is the array of names in code order for list_name().
#pragma once

#include <cstddef>

#define HLACORE_LIST_CODE(name) name,
#define HLACORE_LIST_CODES(none, LIST) none = 0, LIST(HLACORE_LIST_CODE) Count
#define HLACORE_LIST_NAME(name) #name,
#define HLACORE_LIST_NAMES(LIST) {LIST(HLACORE_LIST_NAME)}

namespace hlacore {

// The name of code `code` of a list, or `otherwise` for `none` and codes beyond the list.
template <std::size_t N>
constexpr const char* list_name(const char* const (&names)[N], std::size_t code, const char* otherwise) {
    return code >= 1 && code <= N ? names[code - 1] : otherwise;
}

}  // namespace hlacore
