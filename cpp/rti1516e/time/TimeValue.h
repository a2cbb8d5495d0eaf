// The standard time types' implementation (internal to librti1516e), written once for both: the other operand
// checked to be of the same class, the arithmetic, the 8-byte big-endian
// encoding, and the members of the time, interval and factory classes (HLACORE_TIME_TYPE), which
// HLAfloat64.cpp and HLAinteger64.cpp instantiate.
#ifndef HLACORE_RTI1516E_TIME_TIMEVALUE_H
#define HLACORE_RTI1516E_TIME_TIMEVALUE_H

#include <RTI/Exception.h>
#include <RTI/VariableLengthData.h>

#include "../encoding/Octets.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

namespace hlacore_rti1516e {

// other as a Class; Error if it is of another type.
template <class Class, class Error, class Base>
Class const& as(Base const& other, std::wstring const& expected) {
    auto const* same = dynamic_cast<Class const*>(&other);
    if (!same) throw Error(L"not of the " + expected + L" type");
    return *same;
}

// NaN comes of infinity minus infinity.
inline double checked(double result) {
    if (std::isnan(result)) throw rti1516e::IllegalTimeArithmetic(L"the result is not a number");
    return result;
}
// A time or an interval moved by an interval. A double that the move would leave where it is (t + i rounds to
// t) goes to the next double, so that t + i > t for every positive i, as the standard's axioms have it; an
// integer that would overflow stays at the end of the range (final plus anything is final), as OpenRTI's.
inline double add(double a, double b) {
    const double sum = checked(a + b);
    if (sum != a || b == 0 || !std::isfinite(a)) return sum;
    return std::nextafter(a, b > 0 ? HUGE_VAL : -HUGE_VAL);
}
inline double subtract(double a, double b) { return add(a, -b); }
inline long long add(long long a, long long b) {
    long long result;
    if (__builtin_add_overflow(a, b, &result)) return b > 0 ? INT64_MAX : INT64_MIN;
    return result;
}
inline long long subtract(long long a, long long b) {
    long long result;
    if (__builtin_sub_overflow(a, b, &result)) return b < 0 ? INT64_MAX : INT64_MIN;
    return result;
}
// The interval between two times (setToDifference): one that does not fit is refused.
inline double difference(double a, double b) { return checked(a - b); }
inline long long difference(long long a, long long b) {
    long long result;
    if (__builtin_sub_overflow(a, b, &result)) throw rti1516e::IllegalTimeArithmetic(L"the difference overflows");
    return result;
}

// value's 8 bytes, big-endian (HLAfloat64BE, HLAinteger64BE).
template <class V>
size_t encode8(V value, void* buffer, size_t bufferSize) {
    static_assert(sizeof(V) == 8, "8-byte values only");
    if (bufferSize < 8) throw rti1516e::CouldNotEncode(L"a logical time needs 8 bytes");
    std::uint64_t bits;
    std::memcpy(&bits, &value, 8);
    storeBigEndian(buffer, bits, 8);
    return 8;
}

template <class V>
rti1516e::VariableLengthData encoded(V value) {
    unsigned char bytes[8];
    encode8(value, bytes, sizeof bytes);
    return rti1516e::VariableLengthData(bytes, sizeof bytes);
}

template <class V>
V decode8(void const* buffer, size_t bufferSize) {
    if (bufferSize != 8)
        throw rti1516e::CouldNotDecode(L"a logical time is 8 bytes, not " + std::to_wstring(bufferSize));
    const std::uint64_t bits = loadBigEndian(buffer, 8);
    V value;
    std::memcpy(&value, &bits, 8);
    return value;
}

template <class V>
std::wstring text(V value) {
    std::wostringstream out;
    out << value;
    return out.str();
}

}  // namespace hlacore_rti1516e

// The members of a time or interval class alike in all four: Base is LogicalTime or LogicalTimeInterval, Error
// what an operand of another class throws, Name the time type's name, V the value, Interval the type's interval
// class; get/set its accessors, setZero/isZero and setOne/isOne its two named values (0 and One: initial and
// final, or zero and epsilon).
#define HLACORE_TIME_MEMBERS(Class, Base, Error, Name, V, Interval, get, set, setZero, isZero, setOne, isOne, One)   \
    Class::Class() : _value(0) {}                                                                                 \
    Class::Class(V value) : _value(value) {}                                                                      \
    void Class::setZero() { _value = 0; }                                                                         \
    bool Class::isZero() const { return _value == 0; }                                                            \
    void Class::setOne() { _value = One; }                                                                        \
    bool Class::isOne() const { return _value == One; }                                                           \
    Base& Class::operator+=(LogicalTimeInterval const& addend) {                                                  \
        _value = hlacore_rti1516e::add(_value, Interval(addend).getInterval());                                   \
        return *this;                                                                                             \
    }                                                                                                             \
    Base& Class::operator-=(LogicalTimeInterval const& subtrahend) {                                              \
        _value = hlacore_rti1516e::subtract(_value, Interval(subtrahend).getInterval());                          \
        return *this;                                                                                             \
    }                                                                                                             \
    V Class::get() const { return _value; }                                                                       \
    void Class::set(V value) { _value = value; }                                                                  \
    Class::operator V() const { return _value; }                                                                  \
    Class::Class(Base const& value) : _value(hlacore_rti1516e::as<Class, Error>(value, Name)._value) {}           \
    Class::Class(Class const& value) : Base(), _value(value._value) {}                                           \
    Class::~Class() {}                                                                                            \
    Base& Class::operator=(Base const& value) { return *this = hlacore_rti1516e::as<Class, Error>(value, Name); } \
    Class& Class::operator=(Class const& value) {                                                                 \
        _value = value._value;                                                                                    \
        return *this;                                                                                             \
    }                                                                                                             \
    bool Class::operator>(Base const& value) const {                                                             \
        return _value > hlacore_rti1516e::as<Class, Error>(value, Name)._value;                                   \
    }                                                                                                             \
    bool Class::operator<(Base const& value) const {                                                             \
        return _value < hlacore_rti1516e::as<Class, Error>(value, Name)._value;                                   \
    }                                                                                                             \
    bool Class::operator==(Base const& value) const {                                                            \
        return _value == hlacore_rti1516e::as<Class, Error>(value, Name)._value;                                  \
    }                                                                                                             \
    bool Class::operator>=(Base const& value) const { return !(*this < value); }                                 \
    bool Class::operator<=(Base const& value) const { return !(*this > value); }                                 \
    VariableLengthData Class::encode() const { return hlacore_rti1516e::encoded(_value); }                       \
    size_t Class::encode(void* buffer, size_t bufferSize) const {                                                \
        return hlacore_rti1516e::encode8(_value, buffer, bufferSize);                                             \
    }                                                                                                             \
    size_t Class::encodedLength() const { return 8; }                                                             \
    void Class::decode(VariableLengthData const& data) {                                                         \
        _value = hlacore_rti1516e::decode8<decltype(_value)>(data.data(), data.size());                          \
    }                                                                                                             \
    void Class::decode(void* buffer, size_t bufferSize) {                                                        \
        _value = hlacore_rti1516e::decode8<decltype(_value)>(buffer, bufferSize);                                \
    }                                                                                                             \
    std::wstring Class::toString() const { return hlacore_rti1516e::text(_value); }                              \
    std::wstring Class::implementationName() const { return Name; }

// A factory's two decoders of Result (a Class): from VariableLengthData, and from a buffer.
#define HLACORE_FACTORY_DECODE(Factory, V, decoder, Result, Class)                                                 \
    RTI_UNIQUE_PTR<Result> Factory::decoder(VariableLengthData const& encoded) {                                  \
        return decoder(const_cast<void*>(encoded.data()), encoded.size());                                        \
    }                                                                                                             \
    RTI_UNIQUE_PTR<Result> Factory::decoder(void* buffer, size_t bufferSize) {                                    \
        return RTI_UNIQUE_PTR<Result>(new Class(hlacore_rti1516e::decode8<V>(buffer, bufferSize)));               \
    }

// The time class Time, its interval class Interval and their factory Factory, holding V, named Name, with the
// values Final and Epsilon. Operands of another type are turned away by the converting constructors.
#define HLACORE_TIME_TYPE(Time, Interval, Factory, V, Name, Final, Epsilon)                                        \
    HLACORE_TIME_MEMBERS(Time, LogicalTime, InvalidLogicalTime, Name, V, Interval, getTime, setTime, setInitial,      \
                         isInitial, setFinal, isFinal, Final)                                                        \
    HLACORE_TIME_MEMBERS(Interval, LogicalTimeInterval, InvalidLogicalTimeInterval, Name, V, Interval, getInterval,  \
                         setInterval, setZero, isZero, setEpsilon, isEpsilon, Epsilon)                               \
    void Interval::setToDifference(LogicalTime const& minuend, LogicalTime const& subtrahend) {                    \
        _value = hlacore_rti1516e::difference(Time(minuend).getTime(), Time(subtrahend).getTime());                  \
    }                                                                                                              \
                                                                                                                   \
    Factory::Factory() {}                                                                                          \
    Factory::~Factory() {}                                                                                         \
    RTI_UNIQUE_PTR<Time> Factory::makeLogicalTime(V value) { return RTI_UNIQUE_PTR<Time>(new Time(value)); }       \
    RTI_UNIQUE_PTR<LogicalTime> Factory::makeInitial() { return RTI_UNIQUE_PTR<LogicalTime>(new Time()); }         \
    RTI_UNIQUE_PTR<LogicalTime> Factory::makeFinal() { return RTI_UNIQUE_PTR<LogicalTime>(new Time(Final)); }      \
    RTI_UNIQUE_PTR<Interval> Factory::makeLogicalTimeInterval(V value) {                                           \
        return RTI_UNIQUE_PTR<Interval>(new Interval(value));                                                      \
    }                                                                                                              \
    RTI_UNIQUE_PTR<LogicalTimeInterval> Factory::makeZero() { return RTI_UNIQUE_PTR<LogicalTimeInterval>(new Interval()); } \
    RTI_UNIQUE_PTR<LogicalTimeInterval> Factory::makeEpsilon() {                                                   \
        return RTI_UNIQUE_PTR<LogicalTimeInterval>(new Interval(Epsilon));                                         \
    }                                                                                                              \
    HLACORE_FACTORY_DECODE(Factory, V, decodeLogicalTime, LogicalTime, Time)                                      \
    HLACORE_FACTORY_DECODE(Factory, V, decodeLogicalTimeInterval, LogicalTimeInterval, Interval)                  \
    std::wstring Factory::getName() const { return Name; }

#endif
