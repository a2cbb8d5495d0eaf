#include "exceptions.hpp"

namespace hlacore {

const char* error_name(ErrorCode code) {
    static constexpr const char* kNames[] = HLACORE_LIST_NAMES(HLACORE_EXCEPTIONS);
    return list_name(kNames, static_cast<std::size_t>(code), "");
}

}  // namespace hlacore
