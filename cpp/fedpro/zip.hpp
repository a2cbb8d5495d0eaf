// HLA 4 sends a FOM module compressed as a zip archive (ISO/IEC 21320-1; Pitch's clients compress every module
// over 1 KiB): its one file, read here. Stored or deflated entries (zlib), sizes from the central directory
// (Java's ZipOutputStream writes them after the data), the CRC checked; no ZIP64, no encryption. A decoder of
// outside bytes, fuzzed on its own (cpp/fuzz/fuzz_zip.cpp).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace hlacore::fedpro {

struct BadArchive : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct ZippedFile {
    std::string name;     // as the archive names it
    std::string content;  // at most the limit given
};

// The archive's one file (directories aside). BadArchive saying why: not a zip archive, none or several files,
// a method other than stored or deflated, a size over `max_size`, data that does not inflate to its size and CRC.
ZippedFile unzip_one(std::string_view archive, std::size_t max_size);

}  // namespace hlacore::fedpro
