// HLAinteger64Interval: the span between two HLAinteger64Times. Epsilon is 1; it encodes
// as HLAinteger64BE (8 bytes).
#ifndef RTI_HLAinteger64Interval_h
#define RTI_HLAinteger64Interval_h

#include <RTI/LogicalTime.h>
#include <RTI/LogicalTimeInterval.h>
#include <RTI/SpecificConfig.h>
#include <RTI/encoding/EncodingConfig.h>

namespace rti1516e {

class RTI_EXPORT HLAinteger64Interval : public LogicalTimeInterval {
public:
    HLAinteger64Interval();
    HLAinteger64Interval(Integer64 value);
    // InvalidLogicalTimeInterval unless value is an HLAinteger64Interval.
    HLAinteger64Interval(LogicalTimeInterval const& value);
    HLAinteger64Interval(HLAinteger64Interval const& value);
    ~HLAinteger64Interval() override;

    void setZero() override;
    bool isZero() const override;
    void setEpsilon() override;
    bool isEpsilon() const override;
    // An interval of another type throws InvalidLogicalTimeInterval; a result that overflows throws
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

    virtual Integer64 getInterval() const;
    virtual void setInterval(Integer64 value);
    virtual HLAinteger64Interval& operator=(HLAinteger64Interval const& value);
    operator Integer64() const;

private:
    Integer64 _value;
};

}  // namespace rti1516e

#endif
