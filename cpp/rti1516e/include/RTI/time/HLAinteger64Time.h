// HLAinteger64Time: the standard logical time that is a 64-bit integer (IEEE 1516.1-2010 §12.1). Initial is 0,
// final the largest Integer64; it encodes as HLAinteger64BE (8 bytes).
#ifndef RTI_HLAinteger64Time_h
#define RTI_HLAinteger64Time_h

#include <RTI/LogicalTime.h>
#include <RTI/LogicalTimeInterval.h>
#include <RTI/SpecificConfig.h>
#include <RTI/encoding/EncodingConfig.h>

namespace rti1516e {

class RTI_EXPORT HLAinteger64Time : public LogicalTime {
public:
    HLAinteger64Time();
    HLAinteger64Time(Integer64 value);
    // InvalidLogicalTime unless value is an HLAinteger64Time.
    HLAinteger64Time(LogicalTime const& value);
    HLAinteger64Time(HLAinteger64Time const& value);
    ~HLAinteger64Time() override;

    void setInitial() override;
    bool isInitial() const override;
    void setFinal() override;
    bool isFinal() const override;
    // A time or interval of another type throws InvalidLogicalTime (InvalidLogicalTimeInterval); a result
    // that overflows throws IllegalTimeArithmetic.
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

    virtual Integer64 getTime() const;
    virtual void setTime(Integer64 value);
    virtual HLAinteger64Time& operator=(HLAinteger64Time const& value);
    operator Integer64() const;

private:
    friend class HLAinteger64Interval;
    Integer64 _value;
};

}  // namespace rti1516e

#endif
