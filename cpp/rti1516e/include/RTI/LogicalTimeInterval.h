// A span of logical time (IEEE 1516.1-2010 §12.1): a lookahead, or the difference of two times.
#ifndef RTI_LogicalTimeInterval_h
#define RTI_LogicalTimeInterval_h

#include <RTI/Exception.h>
#include <RTI/SpecificConfig.h>
#include <RTI/VariableLengthData.h>

#include <iosfwd>
#include <string>

// The interface of a logical time or interval (Class): its two named values (setZero/isZero, setOne/isOne:
// initial and final, or zero and epsilon), arithmetic with intervals, order, encoding, and its text; `more`
// is what only one of the two has.
#define RTI1516E_LOGICAL_VALUE_INTERFACE(Class, setZero, isZero, setOne, isOne, more) \
    class RTI_EXPORT Class {                                                          \
    public:                                                                           \
        virtual ~Class() = 0;                                                         \
        virtual void setZero() = 0;                                                   \
        virtual bool isZero() const = 0;                                              \
        virtual void setOne() = 0;                                                    \
        virtual bool isOne() const = 0;                                               \
        virtual Class& operator=(Class const& value) = 0;                             \
        virtual Class& operator+=(LogicalTimeInterval const& addend) = 0;             \
        virtual Class& operator-=(LogicalTimeInterval const& subtrahend) = 0;         \
        virtual bool operator>(Class const& value) const = 0;                         \
        virtual bool operator<(Class const& value) const = 0;                         \
        virtual bool operator==(Class const& value) const = 0;                        \
        virtual bool operator>=(Class const& value) const = 0;                        \
        virtual bool operator<=(Class const& value) const = 0;                        \
        virtual VariableLengthData encode() const = 0;                                \
        virtual size_t encode(void* buffer, size_t bufferSize) const = 0;             \
        virtual size_t encodedLength() const = 0;                                     \
        virtual void decode(VariableLengthData const& encoded) = 0;                   \
        virtual void decode(void* buffer, size_t bufferSize) = 0;                     \
        virtual std::wstring toString() const = 0;                                    \
        virtual std::wstring implementationName() const = 0;                          \
        more                                                                          \
    };                                                                                \
    RTI_EXPORT std::wostream& operator<<(std::wostream& stream, Class const& value);

namespace rti1516e {

class LogicalTime;
class LogicalTimeInterval;
RTI1516E_LOGICAL_VALUE_INTERFACE(LogicalTimeInterval, setZero, isZero, setEpsilon, isEpsilon,
                                 virtual void setToDifference(LogicalTime const& minuend,
                                                              LogicalTime const& subtrahend) = 0;)

}  // namespace rti1516e

#endif
