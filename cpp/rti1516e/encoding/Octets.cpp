// The byte-level helpers the encoding classes share (Octets.h).
#include "Octets.h"

namespace hlacore_rti1516e {

void fail(std::wstring const& message) { throw rti1516e::EncoderException(message); }

void need(Octets const& buffer, size_t index, size_t size) {
    if (index > buffer.size() || buffer.size() - index < size)
        fail(L"need " + std::to_wstring(size) + L" bytes at " + std::to_wstring(index) + L", have " +
             std::to_wstring(buffer.size() > index ? buffer.size() - index : 0));
}

void putBits(Octets& buffer, std::uint64_t bits, size_t size, bool bigEndian) {
    for (size_t i = 0; i < size; ++i) {
        size_t shift = 8 * (bigEndian ? size - 1 - i : i);
        buffer.push_back(static_cast<Octet>((bits >> shift) & 0xff));
    }
}

std::uint64_t getBits(Octets const& buffer, size_t index, size_t size, bool bigEndian) {
    need(buffer, index, size);
    std::uint64_t bits = 0;
    for (size_t i = 0; i < size; ++i) {
        size_t shift = 8 * (bigEndian ? size - 1 - i : i);
        bits |= std::uint64_t(static_cast<unsigned char>(buffer[index + i])) << shift;
    }
    return bits;
}

void putCount(Octets& buffer, size_t count) {
    if (count > 0x7fffffff) fail(L"more than 2^31-1 elements");
    putBits(buffer, count, 4, true);
}

size_t getCount(Octets const& buffer, size_t& index) {
    auto count = static_cast<std::int32_t>(static_cast<std::uint32_t>(getBits(buffer, index, 4, true)));
    if (count < 0) fail(L"negative count " + std::to_wstring(count));
    index += 4;
    return static_cast<size_t>(count);
}

void encodePadded(DataElement const& element, Octets& buffer, size_t start) {
    buffer.resize(buffer.size() + padding(buffer.size() - start, element.getOctetBoundary()), 0);
    element.encodeInto(buffer);
}

size_t decodePadded(DataElement& element, Octets const& buffer, size_t index, size_t start) {
    size_t pad = padding(index - start, element.getOctetBoundary());
    need(buffer, index, pad);
    return element.decodeFrom(buffer, index + pad);
}

size_t paddedEnd(DataElement const& element, size_t position) {
    return position + padding(position, element.getOctetBoundary()) + element.getEncodedLength();
}

rti1516e::VariableLengthData encodeWhole(DataElement const& element) {
    rti1516e::VariableLengthData data;
    encodeWhole(element, data);
    return data;
}

void encodeWhole(DataElement const& element, rti1516e::VariableLengthData& data) {
    Octets buffer;
    element.encodeInto(buffer);
    data.setData(buffer.data(), buffer.size());
}

void decodeWhole(DataElement& element, rti1516e::VariableLengthData const& data) {
    auto const* bytes = static_cast<Octet const*>(data.data());
    Octets buffer(bytes, bytes + data.size());
    size_t end = element.decodeFrom(buffer, 0);
    if (end != buffer.size())
        fail(std::to_wstring(buffer.size() - end) + L" bytes left over after the value");
}

}  // namespace hlacore_rti1516e
