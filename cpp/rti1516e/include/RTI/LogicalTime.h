// A point of logical time (IEEE 1516.1-2010 §12.1): the interface both standard time types implement
// (RTI/time/HLAfloat64Time.h, RTI/time/HLAinteger64Time.h), and a federate's own could.
#ifndef RTI_LogicalTime_h
#define RTI_LogicalTime_h

#include <RTI/Exception.h>
#include <RTI/SpecificConfig.h>
#include <RTI/VariableLengthData.h>

#include <iosfwd>
#include <string>

namespace rti1516e {

class LogicalTimeInterval;

class RTI_EXPORT LogicalTime {
public:
    virtual ~LogicalTime() = 0;
    virtual void setInitial() = 0;
    virtual bool isInitial() const = 0;
    virtual void setFinal() = 0;
    virtual bool isFinal() const = 0;
    virtual LogicalTime& operator=(LogicalTime const& value) = 0;
    virtual LogicalTime& operator+=(LogicalTimeInterval const& addend) = 0;
    virtual LogicalTime& operator-=(LogicalTimeInterval const& subtrahend) = 0;
    virtual bool operator>(LogicalTime const& value) const = 0;
    virtual bool operator<(LogicalTime const& value) const = 0;
    virtual bool operator==(LogicalTime const& value) const = 0;
    virtual bool operator>=(LogicalTime const& value) const = 0;
    virtual bool operator<=(LogicalTime const& value) const = 0;
    virtual VariableLengthData encode() const = 0;
    virtual size_t encode(void* buffer, size_t bufferSize) const = 0;
    virtual size_t encodedLength() const = 0;
    virtual void decode(VariableLengthData const& encodedLogicalTime) = 0;
    virtual void decode(void* buffer, size_t bufferSize) = 0;
    virtual std::wstring toString() const = 0;
    virtual std::wstring implementationName() const = 0;
};

RTI_EXPORT std::wostream& operator<<(std::wostream& stream, LogicalTime const& time);

}  // namespace rti1516e

#endif
