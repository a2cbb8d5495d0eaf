// The enumerators of an append-only X-macro list whose position is the code on the wire
// (HLACORE_MESSAGES, HLACORE_EXCEPTIONS): `none` = 0, then each name of the list from 1, then Count.
#pragma once

#define HLACORE_LIST_CODE(name) name,
#define HLACORE_LIST_CODES(none, LIST) none = 0, LIST(HLACORE_LIST_CODE) Count
