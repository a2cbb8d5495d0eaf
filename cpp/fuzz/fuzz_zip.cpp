// libFuzzer target for the zip reader of the Federate Protocol's compressed FOM modules (cpp/fedpro/zip.hpp):
// arbitrary bytes as an archive. The only exception allowed out is BadArchive; a file read is within the limit.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fedpro/zip.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    constexpr std::size_t kLimit = 1u << 20;
    try {
        const auto file = hlacore::fedpro::unzip_one({reinterpret_cast<const char*>(data), size}, kLimit);
        if (file.content.size() > kLimit) std::abort();
    } catch (hlacore::fedpro::BadArchive const&) {
    }
    return 0;
}
