// HLAfloat64Interval: the span between two HLAfloat64Times. Epsilon is the smallest positive double; it encodes
// as HLAfloat64BE (8 bytes).
#ifndef RTI_HLAfloat64Interval_h
#define RTI_HLAfloat64Interval_h

#include <RTI/LogicalTime.h>
#include <RTI/LogicalTimeInterval.h>
#include <RTI/SpecificConfig.h>

namespace rti1516e {

class RTI_EXPORT HLAfloat64Interval : public LogicalTimeInterval {
public:
    HLAfloat64Interval();
    HLAfloat64Interval(double value);
    // InvalidLogicalTimeInterval unless value is an HLAfloat64Interval.
    HLAfloat64Interval(LogicalTimeInterval const& value);
    HLAfloat64Interval(HLAfloat64Interval const& value);
    ~HLAfloat64Interval() override;

    void setZero() override;
    bool isZero() const override;
    void setEpsilon() override;
    bool isEpsilon() const override;
    // An interval of another type throws InvalidLogicalTimeInterval; a result that is not a number throws
    // IllegalTimeArithmetic.
    LogicalTimeInterval& operator=(LogicalTimeInterval const& value) override;
    LogicalTimeInterval& operator+=(LogicalTimeInterval const& addend) override;
    LogicalTimeInterval& operator-=(LogicalTimeInterval const& subtrahend) override;
    bool operator>(LogicalTimeInterval const& value) const override;
    bool operator<(LogicalTimeInterval const& value) const override;
    bool operator==(LogicalTimeInterval const& value) const override;
    bool operator>=(LogicalTimeInterval const& value) const override;
    bool operator<=(LogicalTimeInterval const& value) const override;
    // Times of another type throw InvalidLogicalTime.
    void setToDifference(LogicalTime const& minuend, LogicalTime const& subtrahend) override;
    VariableLengthData encode() const override;
    size_t encode(void* buffer, size_t bufferSize) const override;
    size_t encodedLength() const override;
    void decode(VariableLengthData const& encodedValue) override;
    void decode(void* buffer, size_t bufferSize) override;
    std::wstring toString() const override;
    std::wstring implementationName() const override;

    virtual double getInterval() const;
    virtual void setInterval(double value);
    virtual HLAfloat64Interval& operator=(HLAfloat64Interval const& value);
    operator double() const;

private:
    double _value;
};

}  // namespace rti1516e

#endif
