#include "fedpro/zip.hpp"

#include <zlib.h>

#include <cstdint>

namespace hlacore::fedpro {

namespace {

constexpr std::uint32_t kEndOfDirectory = 0x06054b50, kDirectoryEntry = 0x02014b50, kLocalHeader = 0x04034b50;
constexpr std::size_t kEndSize = 22, kEntrySize = 46, kLocalSize = 30;

std::uint32_t le(std::string_view bytes, std::size_t at, int n) {
    if (at + std::size_t(n) > bytes.size()) throw BadArchive("a zip archive cut short");
    std::uint32_t v = 0;
    for (int i = n - 1; i >= 0; --i) v = (v << 8) | std::uint8_t(bytes[at + std::size_t(i)]);
    return v;
}

std::string inflated(std::string_view data, std::size_t size) {
    std::string out(size, '\0');
    z_stream z{};
    if (inflateInit2(&z, -MAX_WBITS) != Z_OK) throw BadArchive("zlib cannot start inflating");
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
    z.avail_in = uInt(data.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = uInt(size);
    const int r = inflate(&z, Z_FINISH);
    const bool whole = r == Z_STREAM_END && z.total_out == size;
    inflateEnd(&z);
    if (!whole) throw BadArchive("a deflated file that does not inflate to the size its archive gives");
    return out;
}

}  // namespace

ZippedFile unzip_one(std::string_view a, std::size_t max_size) {
    if (a.size() < kEndSize || a.size() > 0xFFFFFFFFu) throw BadArchive("not a zip archive");
    // The end of the central directory: the last 22 bytes, or earlier by its comment (up to 64 KiB).
    std::size_t end = a.size() - kEndSize;
    while (le(a, end, 4) != kEndOfDirectory) {
        if (end == 0 || a.size() - end > kEndSize + 0xFFFF) throw BadArchive("not a zip archive (no central directory)");
        --end;
    }
    const std::uint32_t entries = le(a, end + 10, 2), directory = le(a, end + 16, 4);
    ZippedFile found;
    int files = 0;
    std::size_t at = directory;
    for (std::uint32_t i = 0; i < entries; ++i) {
        if (le(a, at, 4) != kDirectoryEntry) throw BadArchive("a zip archive whose central directory is broken");
        const std::uint32_t flags = le(a, at + 8, 2), method = le(a, at + 10, 2), crc = le(a, at + 16, 4);
        const std::uint32_t packed = le(a, at + 20, 4), size = le(a, at + 24, 4);
        const std::uint32_t name_size = le(a, at + 28, 2), extra = le(a, at + 30, 2), comment = le(a, at + 32, 2);
        const std::uint32_t local = le(a, at + 42, 4);
        if (at + kEntrySize + name_size > a.size()) throw BadArchive("a zip archive cut short");
        const std::string name(a.substr(at + kEntrySize, name_size));
        at += kEntrySize + name_size + extra + comment;
        if (!name.empty() && name.back() == '/') continue;  // a directory
        if (++files > 1) throw BadArchive("a compressed FOM module holds several files; one is expected");
        if (flags & 1) throw BadArchive("an encrypted zip archive");
        if (packed == 0xFFFFFFFFu || size == 0xFFFFFFFFu) throw BadArchive("a ZIP64 archive, which is not read");
        if (size > max_size)
            throw BadArchive("a compressed FOM module of " + std::to_string(size) + " bytes, over the limit of " +
                             std::to_string(max_size));
        if (le(a, local, 4) != kLocalHeader) throw BadArchive("a zip archive whose file header is broken");
        const std::size_t data = std::size_t(local) + kLocalSize + le(a, local + 26, 2) + le(a, local + 28, 2);
        if (data > a.size() || a.size() - data < packed) throw BadArchive("a zip archive cut short");
        const std::string_view bytes = a.substr(data, packed);
        if (method == 0) {
            if (packed != size) throw BadArchive("a stored file whose sizes differ");
            found.content = std::string(bytes);
        } else if (method == 8) {
            found.content = inflated(bytes, size);
        } else {
            throw BadArchive("a zip method other than stored or deflated (" + std::to_string(method) + ")");
        }
        if (crc32(0L, reinterpret_cast<const Bytef*>(found.content.data()), uInt(found.content.size())) != crc)
            throw BadArchive("a file whose CRC does not match its archive's");
        found.name = name;
    }
    if (files == 0) throw BadArchive("a compressed FOM module that holds no file");
    return found;
}

}  // namespace hlacore::fedpro
