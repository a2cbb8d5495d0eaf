// RTIfedTime and FedTimeFactory (libFedTime).
#include "fedtime.hh"

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>

namespace {

RTI::Boolean boolean(bool b) { return b ? RTI::RTI_TRUE : RTI::RTI_FALSE; }

// The value of a FedTime: this library's times are RTIfedTime.
RTI::Double value_of(const RTI::FedTime& time) {
    const auto* t = dynamic_cast<const RTIfedTime*>(&time);
    if (!t) throw RTI::InvalidFederationTime("not an RTIfedTime: hlacore's logical time is RTIfedTime");
    return t->getTime();
}

constexpr RTI::Double kEpsilon = std::numeric_limits<RTI::Double>::denorm_min();

}  // namespace

RTIfedTime::RTIfedTime() : _fedTime(0) {}
RTIfedTime::RTIfedTime(const RTI::Double& time) : _fedTime(time) {}
RTIfedTime::RTIfedTime(const RTI::FedTime& time) : _fedTime(value_of(time)) {}
RTIfedTime::RTIfedTime(const RTIfedTime& time) : RTI::FedTime(), _fedTime(time._fedTime) {}
RTIfedTime::~RTIfedTime() = default;

void RTIfedTime::setZero() { _fedTime = 0; }
RTI::Boolean RTIfedTime::isZero() { return boolean(_fedTime == 0); }
void RTIfedTime::setEpsilon() { _fedTime = kEpsilon; }
void RTIfedTime::setPositiveInfinity() { _fedTime = std::numeric_limits<RTI::Double>::infinity(); }
RTI::Boolean RTIfedTime::isPositiveInfinity() { return boolean(std::isinf(_fedTime) && _fedTime > 0); }
RTI::Boolean RTIfedTime::isEpsilon() const { return boolean(_fedTime == kEpsilon); }
RTI::Double RTIfedTime::getTime() const { return _fedTime; }

RTI::FedTime& RTIfedTime::operator+=(const RTI::FedTime& other) { return *this += value_of(other); }
RTI::FedTime& RTIfedTime::operator-=(const RTI::FedTime& other) { return *this -= value_of(other); }
RTI::FedTime& RTIfedTime::operator*=(const RTI::FedTime& other) { return *this *= value_of(other); }
RTI::FedTime& RTIfedTime::operator/=(const RTI::FedTime& other) { return *this /= value_of(other); }
RTI::FedTime& RTIfedTime::operator+=(const RTI::Double& other) { _fedTime += other; return *this; }
RTI::FedTime& RTIfedTime::operator-=(const RTI::Double& other) { _fedTime -= other; return *this; }
RTI::FedTime& RTIfedTime::operator*=(const RTI::Double& other) { _fedTime *= other; return *this; }
RTI::FedTime& RTIfedTime::operator/=(const RTI::Double& other) { _fedTime /= other; return *this; }

RTI::Boolean RTIfedTime::operator<=(const RTI::FedTime& other) const { return boolean(_fedTime <= value_of(other)); }
RTI::Boolean RTIfedTime::operator<(const RTI::FedTime& other) const { return boolean(_fedTime < value_of(other)); }
RTI::Boolean RTIfedTime::operator>=(const RTI::FedTime& other) const { return boolean(_fedTime >= value_of(other)); }
RTI::Boolean RTIfedTime::operator>(const RTI::FedTime& other) const { return boolean(_fedTime > value_of(other)); }
RTI::Boolean RTIfedTime::operator==(const RTI::FedTime& other) const { return boolean(_fedTime == value_of(other)); }
RTI::Boolean RTIfedTime::operator!=(const RTI::FedTime& other) const { return boolean(_fedTime != value_of(other)); }
RTI::Boolean RTIfedTime::operator==(const RTI::Double& other) const { return boolean(_fedTime == other); }
RTI::Boolean RTIfedTime::operator!=(const RTI::Double& other) const { return boolean(_fedTime != other); }
RTI::Boolean RTIfedTime::operator<=(const RTI::Double& other) const { return boolean(_fedTime <= other); }
RTI::Boolean RTIfedTime::operator<(const RTI::Double& other) const { return boolean(_fedTime < other); }
RTI::Boolean RTIfedTime::operator>=(const RTI::Double& other) const { return boolean(_fedTime >= other); }
RTI::Boolean RTIfedTime::operator>(const RTI::Double& other) const { return boolean(_fedTime > other); }

RTI::FedTime& RTIfedTime::operator=(const RTI::FedTime& other) { _fedTime = value_of(other); return *this; }
RTI::FedTime& RTIfedTime::operator=(const RTIfedTime& other) { _fedTime = other._fedTime; return *this; }
RTI::FedTime& RTIfedTime::operator=(const RTI::Double& other) { _fedTime = other; return *this; }

RTIfedTime RTIfedTime::operator+(const RTI::FedTime& other) const { return _fedTime + value_of(other); }
RTIfedTime RTIfedTime::operator+(const RTI::Double& other) const { return _fedTime + other; }
RTIfedTime RTIfedTime::operator-(const RTI::FedTime& other) const { return _fedTime - value_of(other); }
RTIfedTime RTIfedTime::operator-(const RTI::Double& other) const { return _fedTime - other; }
RTIfedTime RTIfedTime::operator*(const RTI::FedTime& other) const { return _fedTime * value_of(other); }
RTIfedTime RTIfedTime::operator*(const RTI::Double& other) const { return _fedTime * other; }
RTIfedTime RTIfedTime::operator/(const RTI::FedTime& other) const { return _fedTime / value_of(other); }
RTIfedTime RTIfedTime::operator/(const RTI::Double& other) const { return _fedTime / other; }

RTIfedTime operator+(const RTI::Double& left, const RTI::FedTime& right) { return left + value_of(right); }
RTIfedTime operator-(const RTI::Double& left, const RTI::FedTime& right) { return left - value_of(right); }
RTIfedTime operator*(const RTI::Double& left, const RTI::FedTime& right) { return left * value_of(right); }
RTIfedTime operator/(const RTI::Double& left, const RTI::FedTime& right) { return left / value_of(right); }

int RTIfedTime::encodedLength() const { return 8; }

void RTIfedTime::encode(char* buffer) const {
    std::uint64_t bits;
    std::memcpy(&bits, &_fedTime, 8);
    for (int i = 7; i >= 0; --i, bits >>= 8) buffer[i] = static_cast<char>(bits & 0xff);
}

int RTIfedTime::getPrintableLength() const { return std::snprintf(nullptr, 0, "%.17g", _fedTime) + 1; }

void RTIfedTime::getPrintableString(char* buffer) {
    std::snprintf(buffer, static_cast<std::size_t>(getPrintableLength()), "%.17g", _fedTime);
}

std::ostream& operator<<(std::ostream& os, const RTI::FedTime& time) {
    return os << value_of(time);
}

RTI::FedTime* RTI::FedTimeFactory::makeZero() { return new RTIfedTime(0.0); }

RTI::FedTime* RTI::FedTimeFactory::decode(const char* buffer) {
    std::uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits = (bits << 8) | static_cast<unsigned char>(buffer[i]);
    RTI::Double time;
    std::memcpy(&time, &bits, 8);
    return new RTIfedTime(time);
}
