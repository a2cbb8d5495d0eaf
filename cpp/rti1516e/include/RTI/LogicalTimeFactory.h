// Makes the times and intervals of one time implementation by its name. HLAlogicalTimeFactoryFactory
// (librti1516e) knows the standard two, "HLAfloat64Time" and "HLAinteger64Time" ("" is the first);
// LogicalTimeFactoryFactory (libfedtime1516e) is where a federation's own time type would be made.
#ifndef RTI_LogicalTimeFactory_h
#define RTI_LogicalTimeFactory_h

#include <RTI/Exception.h>
#include <RTI/SpecificConfig.h>

#include <memory>
#include <string>

namespace rti1516e {

class LogicalTime;
class LogicalTimeInterval;
class VariableLengthData;

class RTI_EXPORT LogicalTimeFactory {
public:
    virtual ~LogicalTimeFactory() = 0;
    virtual RTI_UNIQUE_PTR<LogicalTime> makeInitial() = 0;
    virtual RTI_UNIQUE_PTR<LogicalTime> makeFinal() = 0;
    virtual RTI_UNIQUE_PTR<LogicalTimeInterval> makeZero() = 0;
    virtual RTI_UNIQUE_PTR<LogicalTimeInterval> makeEpsilon() = 0;
    virtual RTI_UNIQUE_PTR<LogicalTime> decodeLogicalTime(VariableLengthData const& encodedLogicalTime) = 0;
    virtual RTI_UNIQUE_PTR<LogicalTime> decodeLogicalTime(void* buffer, size_t bufferSize) = 0;
    virtual RTI_UNIQUE_PTR<LogicalTimeInterval> decodeLogicalTimeInterval(VariableLengthData const& encodedValue) = 0;
    virtual RTI_UNIQUE_PTR<LogicalTimeInterval> decodeLogicalTimeInterval(void* buffer, size_t bufferSize) = 0;
    virtual std::wstring getName() const = 0;
};

class RTI_EXPORT HLAlogicalTimeFactoryFactory {
public:
    // Null for a name it does not know.
    static RTI_UNIQUE_PTR<LogicalTimeFactory> makeLogicalTimeFactory(std::wstring const& implementationName);
};

class RTI_EXPORT_FEDTIME LogicalTimeFactoryFactory {
public:
    static RTI_UNIQUE_PTR<LogicalTimeFactory> makeLogicalTimeFactory(std::wstring const& implementationName);
};

}  // namespace rti1516e

#endif
