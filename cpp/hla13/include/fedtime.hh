// RTIfedTime (libFedTime): HLA 1.3 logical time as a double, with the arithmetic and comparisons the
// other RTIs' RTIfedTime has. Epsilon is the smallest positive double; infinity is the double's.
#ifndef HLACORE_FEDTIME_HH
#define HLACORE_FEDTIME_HH

#include "RTI.hh"

class FEDTIME_EXPORT RTIfedTime : public RTI::FedTime {
public:
    RTIfedTime();
    RTIfedTime(const RTI::Double& time);
    RTIfedTime(const RTI::FedTime& time);
    RTIfedTime(const RTIfedTime& time);
    ~RTIfedTime() override;

    void setZero() override;
    RTI::Boolean isZero() override;
    void setEpsilon() override;
    void setPositiveInfinity() override;
    RTI::Boolean isPositiveInfinity() override;
    RTI::FedTime& operator+=(const RTI::FedTime& other) override;
    RTI::FedTime& operator-=(const RTI::FedTime& other) override;
    RTI::Boolean operator<=(const RTI::FedTime& other) const override;
    RTI::Boolean operator<(const RTI::FedTime& other) const override;
    RTI::Boolean operator>=(const RTI::FedTime& other) const override;
    RTI::Boolean operator>(const RTI::FedTime& other) const override;
    RTI::Boolean operator==(const RTI::FedTime& other) const override;
    RTI::FedTime& operator=(const RTI::FedTime& other) override;
    // The encoding is the double's 8 bytes in network (big-endian) order.
    int encodedLength() const override;
    void encode(char* buffer) const override;
    int getPrintableLength() const override;  // with the terminating NUL
    void getPrintableString(char* buffer) override;

    RTI::Boolean isEpsilon() const;
    RTI::Double getTime() const;

    RTI::Boolean operator==(const RTI::Double& other) const;
    RTI::Boolean operator!=(const RTI::FedTime& other) const;
    RTI::Boolean operator!=(const RTI::Double& other) const;
    RTI::Boolean operator<=(const RTI::Double& other) const;
    RTI::Boolean operator<(const RTI::Double& other) const;
    RTI::Boolean operator>=(const RTI::Double& other) const;
    RTI::Boolean operator>(const RTI::Double& other) const;

    RTI::FedTime& operator=(const RTIfedTime& other);
    RTI::FedTime& operator=(const RTI::Double& other);
    RTI::FedTime& operator*=(const RTI::FedTime& other);
    RTI::FedTime& operator/=(const RTI::FedTime& other);
    RTI::FedTime& operator+=(const RTI::Double& other);
    RTI::FedTime& operator-=(const RTI::Double& other);
    RTI::FedTime& operator*=(const RTI::Double& other);
    RTI::FedTime& operator/=(const RTI::Double& other);

    RTIfedTime operator+(const RTI::FedTime& other) const;
    RTIfedTime operator+(const RTI::Double& other) const;
    RTIfedTime operator-(const RTI::FedTime& other) const;
    RTIfedTime operator-(const RTI::Double& other) const;
    RTIfedTime operator*(const RTI::FedTime& other) const;
    RTIfedTime operator*(const RTI::Double& other) const;
    RTIfedTime operator/(const RTI::FedTime& other) const;
    RTIfedTime operator/(const RTI::Double& other) const;

private:
    RTI::Double _fedTime;
};

FEDTIME_EXPORT RTIfedTime operator+(const RTI::Double& left, const RTI::FedTime& right);
FEDTIME_EXPORT RTIfedTime operator-(const RTI::Double& left, const RTI::FedTime& right);
FEDTIME_EXPORT RTIfedTime operator*(const RTI::Double& left, const RTI::FedTime& right);
FEDTIME_EXPORT RTIfedTime operator/(const RTI::Double& left, const RTI::FedTime& right);
FEDTIME_EXPORT RTI_STD::ostream& operator<<(RTI_STD::ostream& os, const RTI::FedTime& time);

#endif
