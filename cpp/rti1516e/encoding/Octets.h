// What the encoding helpers share at the byte level (internal to librti1516e): bounds checks, HLAinteger32BE
// counts, padding counted from a composite's start, and encode/decode of a whole VariableLengthData.
#ifndef HLACORE_RTI1516E_ENCODING_OCTETS_H
#define HLACORE_RTI1516E_ENCODING_OCTETS_H

#include <RTI/VariableLengthData.h>
#include <RTI/encoding/DataElement.h>

#include <cstdint>
#include <string>
#include <vector>

namespace hlacore_rti1516e {

using rti1516e::DataElement;
using rti1516e::Octet;
using Octets = std::vector<Octet>;

[[noreturn]] void fail(std::wstring const& message);
// size bytes of bits at out, most significant first, and back (the handles' and times' encodings).
inline void storeBigEndian(void* out, std::uint64_t bits, size_t size) {
    auto* bytes = static_cast<unsigned char*>(out);
    for (size_t i = 0; i < size; ++i) bytes[i] = static_cast<unsigned char>(bits >> (8 * (size - 1 - i)));
}
inline std::uint64_t loadBigEndian(void const* in, size_t size) {
    auto const* bytes = static_cast<unsigned char const*>(in);
    std::uint64_t bits = 0;
    for (size_t i = 0; i < size; ++i) bits = bits << 8 | bytes[i];
    return bits;
}
// Throws unless buffer holds size bytes from index.
void need(Octets const& buffer, size_t index, size_t size);
// Appends the size low bytes of bits, most significant first when bigEndian.
void putBits(Octets& buffer, std::uint64_t bits, size_t size, bool bigEndian);
std::uint64_t getBits(Octets const& buffer, size_t index, size_t size, bool bigEndian);
void putCount(Octets& buffer, size_t count);
// The count at index (negative ones throw); index moves past it.
size_t getCount(Octets const& buffer, size_t& index);

// The pad bytes that bring position to a multiple of boundary.
inline size_t padding(size_t position, unsigned boundary) {
    return boundary > 1 ? (boundary - position % boundary) % boundary : 0;
}
// element, after the padding to its boundary counted from start (where its composite begins).
void encodePadded(DataElement const& element, Octets& buffer, size_t start);
size_t decodePadded(DataElement& element, Octets const& buffer, size_t index, size_t start);
// Where element ends when it follows position (both counted from its composite's start).
size_t paddedEnd(DataElement const& element, size_t position);

rti1516e::VariableLengthData encodeWhole(DataElement const& element);
void encodeWhole(DataElement const& element, rti1516e::VariableLengthData& data);
// Bytes left over are an error.
void decodeWhole(DataElement& element, rti1516e::VariableLengthData const& data);

}  // namespace hlacore_rti1516e

// The three members every element implements the same way, from encodeInto and decodeFrom.
#define HLACORE_WHOLE_ENCODING(Class)                                                                          \
    rti1516e::VariableLengthData Class::encode() const { return hlacore_rti1516e::encodeWhole(*this); }       \
    void Class::encode(rti1516e::VariableLengthData& inData) const { hlacore_rti1516e::encodeWhole(*this, inData); } \
    void Class::decode(rti1516e::VariableLengthData const& inData) { hlacore_rti1516e::decodeWhole(*this, inData); }

// A composite's copy (its implementation copied: the copy owns copies of the members), destructor, clone and
// whole encodings.
#define HLACORE_COMPOSITE_MEMBERS(Class)                                                                        \
    Class::Class(Class const& rhs) : DataElement(), _impl(new Class##Implementation(*rhs._impl)) {}             \
    Class::~Class() {}                                                                                          \
    RTI_UNIQUE_PTR<DataElement> Class::clone() const { return RTI_UNIQUE_PTR<DataElement>(new Class(*this)); } \
    HLACORE_WHOLE_ENCODING(Class)

#endif
