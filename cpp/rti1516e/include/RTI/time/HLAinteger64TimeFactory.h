// HLAinteger64TimeFactory: makes and decodes HLAinteger64Times and HLAinteger64Intervals; its name is
// L"HLAinteger64Time", the name a federation is created with to use them.
#ifndef RTI_HLAinteger64TimeFactory_h
#define RTI_HLAinteger64TimeFactory_h

#include <RTI/LogicalTimeFactory.h>
#include <RTI/SpecificConfig.h>
#include <RTI/time/HLAinteger64Interval.h>
#include <RTI/time/HLAinteger64Time.h>

#include <string>

namespace rti1516e {

const std::wstring HLAinteger64TimeName(L"HLAinteger64Time");

class RTI_EXPORT HLAinteger64TimeFactory : public LogicalTimeFactory {
public:
    HLAinteger64TimeFactory();
    ~HLAinteger64TimeFactory() override;
    virtual RTI_UNIQUE_PTR<HLAinteger64Time> makeLogicalTime(Integer64 value);
    RTI_UNIQUE_PTR<LogicalTime> makeInitial() override;
    RTI_UNIQUE_PTR<LogicalTime> makeFinal() override;
    virtual RTI_UNIQUE_PTR<HLAinteger64Interval> makeLogicalTimeInterval(Integer64 value);
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
