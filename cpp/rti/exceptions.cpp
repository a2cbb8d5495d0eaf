#include "exceptions.hpp"

namespace hlacore {

const char* error_name(ErrorCode code) {
    switch (code) {
#define HLACORE_X(name) \
    case ErrorCode::name: return #name;
        HLACORE_EXCEPTIONS(HLACORE_X)
#undef HLACORE_X
        default: return "";
    }
}

}  // namespace hlacore
