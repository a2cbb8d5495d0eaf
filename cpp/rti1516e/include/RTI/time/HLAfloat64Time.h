// HLAfloat64Time: the standard logical time that is a double (IEEE 1516.1-2010 §12.1). Initial is 0, final
// +infinity; it encodes as HLAfloat64BE (8 bytes).
#ifndef RTI_HLAfloat64Time_h
#define RTI_HLAfloat64Time_h

#include <RTI/LogicalTime.h>
#include <RTI/LogicalTimeInterval.h>
#include <RTI/SpecificConfig.h>

namespace rti1516e {

class RTI_EXPORT HLAfloat64Time : public LogicalTime {
public:
    HLAfloat64Time();
    HLAfloat64Time(double const& value);
    // InvalidLogicalTime unless value is an HLAfloat64Time.
    HLAfloat64Time(LogicalTime const& value);
    HLAfloat64Time(HLAfloat64Time const& value);
    ~HLAfloat64Time() override;

    void setInitial() override;
    bool isInitial() const override;
    void setFinal() override;
    bool isFinal() const override;
    // A time or interval of another type throws InvalidLogicalTime (InvalidLogicalTimeInterval); a sum that is
    // not a number (final minus final) throws IllegalTimeArithmetic.
    LogicalTime& operator=(LogicalTime const& value) override;
    LogicalTime& operator+=(LogicalTimeInterval const& addend) override;
    LogicalTime& operator-=(LogicalTimeInterval const& subtrahend) override;
    bool operator>(LogicalTime const& value) const override;
    bool operator<(LogicalTime const& value) const override;
    bool operator==(LogicalTime const& value) const override;
    bool operator>=(LogicalTime const& value) const override;
    bool operator<=(LogicalTime const& value) const override;
    VariableLengthData encode() const override;
    // CouldNotEncode when bufferSize is under 8; returns 8.
    size_t encode(void* buffer, size_t bufferSize) const override;
    size_t encodedLength() const override;
    // CouldNotDecode unless there are exactly 8 bytes.
    void decode(VariableLengthData const& encodedLogicalTime) override;
    void decode(void* buffer, size_t bufferSize) override;
    std::wstring toString() const override;
    std::wstring implementationName() const override;

    virtual double getTime() const;
    virtual void setTime(double value);
    virtual HLAfloat64Time& operator=(HLAfloat64Time const& value);
    operator double() const;

private:
    friend class HLAfloat64Interval;
    double _value;
};

}  // namespace rti1516e

#endif
