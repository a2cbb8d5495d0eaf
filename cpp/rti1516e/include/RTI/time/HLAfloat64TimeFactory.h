// HLAfloat64TimeFactory: makes and decodes HLAfloat64Times and HLAfloat64Intervals; its name is
// L"HLAfloat64Time", the name a federation is created with to use them.
#ifndef RTI_HLAfloat64TimeFactory_h
#define RTI_HLAfloat64TimeFactory_h

#include <RTI/LogicalTimeFactory.h>
#include <RTI/SpecificConfig.h>
#include <RTI/time/HLAfloat64Interval.h>
#include <RTI/time/HLAfloat64Time.h>

#include <string>

namespace rti1516e {

const std::wstring HLAfloat64TimeName(L"HLAfloat64Time");

class RTI_EXPORT HLAfloat64TimeFactory : public LogicalTimeFactory {
public:
    HLAfloat64TimeFactory();
    ~HLAfloat64TimeFactory() override;
    virtual RTI_UNIQUE_PTR<HLAfloat64Time> makeLogicalTime(double value);
    RTI_UNIQUE_PTR<LogicalTime> makeInitial() override;
    RTI_UNIQUE_PTR<LogicalTime> makeFinal() override;
    virtual RTI_UNIQUE_PTR<HLAfloat64Interval> makeLogicalTimeInterval(double value);
    RTI_UNIQUE_PTR<LogicalTimeInterval> makeZero() override;
    RTI_UNIQUE_PTR<LogicalTimeInterval> makeEpsilon() override;
    // CouldNotDecode unless there are exactly 8 bytes.
    RTI_UNIQUE_PTR<LogicalTime> decodeLogicalTime(VariableLengthData const& encodedLogicalTime) override;
    RTI_UNIQUE_PTR<LogicalTime> decodeLogicalTime(void* buffer, size_t bufferSize) override;
    RTI_UNIQUE_PTR<LogicalTimeInterval> decodeLogicalTimeInterval(VariableLengthData const& encodedValue) override;
    RTI_UNIQUE_PTR<LogicalTimeInterval> decodeLogicalTimeInterval(void* buffer, size_t bufferSize) override;
    std::wstring getName() const override;
};

}  // namespace rti1516e

#endif
