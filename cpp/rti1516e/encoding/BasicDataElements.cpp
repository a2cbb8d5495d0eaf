// The basic data elements: one codec per kind of encoding (numbers as their bit patterns, booleans, octet pairs,
// UTF-16 characters and strings), and every class's members defined once, by BASIC_DATA_ELEMENT, from its codec.
#include <RTI/encoding/BasicDataElements.h>

#include <cstdint>
#include <cstring>
#include <cwchar>
#include <type_traits>

#include "Octets.h"

namespace {

using namespace hlacore_rti1516e;

template <size_t N>
using Unsigned = std::conditional_t<N == 1, std::uint8_t,
                 std::conditional_t<N == 2, std::uint16_t, std::conditional_t<N == 4, std::uint32_t, std::uint64_t>>>;

// Integers (two's complement) and floats (IEEE 754): their bit pattern, in one byte order.
template <class T, bool BigEndian>
struct Number {
    static constexpr unsigned boundary = sizeof(T);
    static size_t length(T const&) { return sizeof(T); }
    static void put(Octets& buffer, T value) {
        Unsigned<sizeof(T)> bits;
        std::memcpy(&bits, &value, sizeof(T));
        putBits(buffer, bits, sizeof(T), BigEndian);
    }
    static size_t get(Octets const& buffer, size_t index, T& value) {
        auto bits = static_cast<Unsigned<sizeof(T)>>(getBits(buffer, index, sizeof(T), BigEndian));
        std::memcpy(&value, &bits, sizeof(T));
        return index + sizeof(T);
    }
};

template <class T>
using BE = Number<T, true>;
template <class T>
using LE = Number<T, false>;

// HLAboolean: an HLAinteger32BE, 1 for true; any other value than 0 decodes as true.
struct Boolean {
    static constexpr unsigned boundary = 4;
    static size_t length(bool) { return 4; }
    static void put(Octets& buffer, bool value) { putBits(buffer, value ? 1 : 0, 4, true); }
    static size_t get(Octets const& buffer, size_t index, bool& value) {
        value = getBits(buffer, index, 4, true) != 0;
        return index + 4;
    }
};

template <bool BigEndian>
struct Pair {
    static constexpr unsigned boundary = 2;
    static size_t length(rti1516e::OctetPair const&) { return 2; }
    static void put(Octets& buffer, rti1516e::OctetPair const& value) {
        buffer.push_back(BigEndian ? value.first : value.second);
        buffer.push_back(BigEndian ? value.second : value.first);
    }
    static size_t get(Octets const& buffer, size_t index, rti1516e::OctetPair& value) {
        need(buffer, index, 2);
        value = BigEndian ? rti1516e::OctetPair(buffer[index], buffer[index + 1])
                          : rti1516e::OctetPair(buffer[index + 1], buffer[index]);
        return index + 2;
    }
};

struct UnicodeChar {
    static constexpr unsigned boundary = 2;
    static size_t length(wchar_t) { return 2; }
    static void put(Octets& buffer, wchar_t value) {
        auto code = static_cast<std::uint32_t>(value);
        if (code > 0xffff) {
            wchar_t hex[16];
            std::swprintf(hex, 16, L"%X", static_cast<unsigned>(code));
            fail(L"HLAunicodeChar: U+" + std::wstring(hex) + L" is not one UTF-16 unit");
        }
        putBits(buffer, code, 2, true);
    }
    static size_t get(Octets const& buffer, size_t index, wchar_t& value) {
        value = static_cast<wchar_t>(getBits(buffer, index, 2, true));
        return index + 2;
    }
};

// The UTF-16 code units of text: a wchar_t beyond U+FFFF (where wchar_t has 32 bits) becomes a surrogate pair.
std::vector<std::uint16_t> utf16(std::wstring const& text) {
    std::vector<std::uint16_t> units;
    for (wchar_t c : text) {
        auto code = static_cast<std::uint32_t>(c);
        if (code > 0x10ffff) fail(L"HLAunicodeString: " + std::to_wstring(code) + L" is not a character");
        if (code > 0xffff) {
            code -= 0x10000;
            units.push_back(static_cast<std::uint16_t>(0xd800 + (code >> 10)));
            units.push_back(static_cast<std::uint16_t>(0xdc00 + (code & 0x3ff)));
        } else {
            units.push_back(static_cast<std::uint16_t>(code));
        }
    }
    return units;
}

struct UnicodeString {
    static constexpr unsigned boundary = 4;
    static size_t length(std::wstring const& value) { return 4 + 2 * utf16(value).size(); }
    static void put(Octets& buffer, std::wstring const& value) {
        auto units = utf16(value);
        putCount(buffer, units.size());
        for (auto unit : units) putBits(buffer, unit, 2, true);
    }
    static size_t get(Octets const& buffer, size_t index, std::wstring& value) {
        size_t count = getCount(buffer, index);
        need(buffer, index, 2 * count);
        std::wstring text;
        for (size_t i = 0; i < count; ++i, index += 2) {
            auto unit = static_cast<std::uint32_t>(getBits(buffer, index, 2, true));
            bool pair = sizeof(wchar_t) == 4 && unit >= 0xd800 && unit < 0xdc00 && i + 1 < count;
            auto low = pair ? static_cast<std::uint32_t>(getBits(buffer, index + 2, 2, true)) : 0;
            if (pair && low >= 0xdc00 && low < 0xe000) {
                unit = 0x10000 + ((unit - 0xd800) << 10) + (low - 0xdc00);
                ++i, index += 2;
            }
            text.push_back(static_cast<wchar_t>(unit));
        }
        value = text;
        return index;
    }
};

struct AsciiString {
    static constexpr unsigned boundary = 4;
    static size_t length(std::string const& value) { return 4 + value.size(); }
    static void put(Octets& buffer, std::string const& value) {
        putCount(buffer, value.size());
        buffer.insert(buffer.end(), value.begin(), value.end());
    }
    static size_t get(Octets const& buffer, size_t index, std::string& value) {
        size_t count = getCount(buffer, index);
        need(buffer, index, count);
        value.assign(buffer.begin() + index, buffer.begin() + index + count);
        return index + count;
    }
};

}  // namespace

namespace rti1516e {

// A decode that fails leaves the value as it was.
#define BASIC_DATA_ELEMENT(Name, Value, Codec)                                                                 \
    Name::Name() : _value(), _data(&_value) {}                                                                  \
    Name::Name(Value const& inData) : _value(inData), _data(&_value) {}                                         \
    Name::Name(Value* inData) : _value(), _data(inData ? inData : &_value) {}                                   \
    Name::Name(Name const& rhs) : DataElement(), _value(rhs.get()), _data(&_value) {}                           \
    Name::~Name() {}                                                                                            \
    Name& Name::operator=(Name const& rhs) {                                                                    \
        *_data = rhs.get();                                                                                     \
        return *this;                                                                                           \
    }                                                                                                           \
    RTI_UNIQUE_PTR<DataElement> Name::clone() const { return RTI_UNIQUE_PTR<DataElement>(new Name(*this)); }   \
    HLACORE_WHOLE_ENCODING(Name)                                                                                \
    void Name::encodeInto(std::vector<Octet>& buffer) const { Codec::put(buffer, *_data); }                    \
    size_t Name::decodeFrom(std::vector<Octet> const& buffer, size_t index) {                                  \
        Value value{};                                                                                          \
        size_t end = Codec::get(buffer, index, value);                                                          \
        *_data = value;                                                                                         \
        return end;                                                                                             \
    }                                                                                                           \
    size_t Name::getEncodedLength() const { return Codec::length(*_data); }                                    \
    unsigned int Name::getOctetBoundary() const { return Codec::boundary; }                                    \
    Integer64 Name::hash() const { return DataElement::hash(); }                                                \
    void Name::setDataPointer(Value* inData) {                                                                  \
        if (!inData) fail(L"" #Name L": null data pointer");                                                    \
        _data = inData;                                                                                         \
    }                                                                                                           \
    void Name::set(Value inData) { *_data = inData; }                                                           \
    Value Name::get() const { return *_data; }                                                                  \
    Name& Name::operator=(Value rhs) {                                                                          \
        *_data = rhs;                                                                                           \
        return *this;                                                                                           \
    }                                                                                                           \
    Name::operator Value() const { return *_data; }

BASIC_DATA_ELEMENT(HLAASCIIchar, char, BE<char>)
BASIC_DATA_ELEMENT(HLAASCIIstring, std::string, AsciiString)
BASIC_DATA_ELEMENT(HLAboolean, bool, Boolean)
BASIC_DATA_ELEMENT(HLAbyte, Octet, BE<Octet>)
BASIC_DATA_ELEMENT(HLAfloat32BE, float, BE<float>)
BASIC_DATA_ELEMENT(HLAfloat32LE, float, LE<float>)
BASIC_DATA_ELEMENT(HLAfloat64BE, double, BE<double>)
BASIC_DATA_ELEMENT(HLAfloat64LE, double, LE<double>)
BASIC_DATA_ELEMENT(HLAinteger16BE, Integer16, BE<Integer16>)
BASIC_DATA_ELEMENT(HLAinteger16LE, Integer16, LE<Integer16>)
BASIC_DATA_ELEMENT(HLAinteger32BE, Integer32, BE<Integer32>)
BASIC_DATA_ELEMENT(HLAinteger32LE, Integer32, LE<Integer32>)
BASIC_DATA_ELEMENT(HLAinteger64BE, Integer64, BE<Integer64>)
BASIC_DATA_ELEMENT(HLAinteger64LE, Integer64, LE<Integer64>)
BASIC_DATA_ELEMENT(HLAoctet, Octet, BE<Octet>)
BASIC_DATA_ELEMENT(HLAoctetPairBE, OctetPair, Pair<true>)
BASIC_DATA_ELEMENT(HLAoctetPairLE, OctetPair, Pair<false>)
BASIC_DATA_ELEMENT(HLAunicodeChar, wchar_t, UnicodeChar)
BASIC_DATA_ELEMENT(HLAunicodeString, std::wstring, UnicodeString)

#undef BASIC_DATA_ELEMENT

}  // namespace rti1516e
