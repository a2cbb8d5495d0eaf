// The two standard time types of IEEE 1516.1-2010 §12.1, each a time, an interval and a factory of the same
// shape over its value: HLAfloat64Time (a double: initial 0, final +infinity, epsilon the smallest positive
// double) and HLAinteger64Time (an Integer64: initial 0, final the largest, epsilon 1). Both encode as their
// big-endian value, 8 bytes. The standard's headers (HLAfloat64Time.h, ...) each include this one.
//
// Errors: a time or interval of another type is InvalidLogicalTime (InvalidLogicalTimeInterval); a result
// that is not a number (final minus final) or that overflows is IllegalTimeArithmetic; encoding into fewer
// than 8 bytes is CouldNotEncode, decoding other than 8 bytes CouldNotDecode.
#ifndef RTI_HLAtimeTypes_h
#define RTI_HLAtimeTypes_h

#include <RTI/LogicalTime.h>
#include <RTI/LogicalTimeFactory.h>
#include <RTI/LogicalTimeInterval.h>
#include <RTI/SpecificConfig.h>
#include <RTI/encoding/EncodingConfig.h>

#include <string>

// A time or an interval over Value (Base: LogicalTime or LogicalTimeInterval): get/set its accessors,
// setZero/isZero and setOne/isOne its two named values (initial and final, or zero and epsilon), then what
// only one of the two has.
#define RTI1516E_TIME_VALUE_CLASS(Class, Base, Value, get, set, setZero, isZero, setOne, isOne, more) \
    class RTI_EXPORT Class : public Base {                                  \
    public:                                                                \
        Class();                                                           \
        Class(Value value);                                                \
        Class(Base const& value);                                          \
        Class(Class const& value);                                         \
        ~Class() override;                                                 \
        void setZero() override;                                           \
        bool isZero() const override;                                      \
        void setOne() override;                                            \
        bool isOne() const override;                                       \
        Base& operator=(Base const& value) override;                       \
        Base& operator+=(LogicalTimeInterval const& addend) override;      \
        Base& operator-=(LogicalTimeInterval const& subtrahend) override;  \
        bool operator>(Base const& value) const override;                  \
        bool operator<(Base const& value) const override;                  \
        bool operator==(Base const& value) const override;                 \
        bool operator>=(Base const& value) const override;                 \
        bool operator<=(Base const& value) const override;                 \
        VariableLengthData encode() const override;                        \
        size_t encode(void* buffer, size_t bufferSize) const override;     \
        size_t encodedLength() const override;                             \
        void decode(VariableLengthData const& encoded) override;           \
        void decode(void* buffer, size_t bufferSize) override;             \
        std::wstring toString() const override;                            \
        std::wstring implementationName() const override;                  \
        virtual Class& operator=(Class const& value);                      \
        operator Value() const;                                            \
        virtual Value get() const;                                         \
        virtual void set(Value value);                                     \
        more                                                               \
                                                                           \
    private:                                                               \
        Value _value;                                                      \
    };

// The factory's name is the name a federation is created with to use the type.
#define RTI1516E_TIME_FACTORY_CLASS(Factory, Time, Interval, Value)        \
    const std::wstring Time##Name(L"" #Time);                              \
    class RTI_EXPORT Factory : public LogicalTimeFactory {                 \
    public:                                                                \
        Factory();                                                         \
        ~Factory() override;                                               \
        virtual RTI_UNIQUE_PTR<Time> makeLogicalTime(Value value);         \
        RTI_UNIQUE_PTR<LogicalTime> makeInitial() override;                \
        RTI_UNIQUE_PTR<LogicalTime> makeFinal() override;                  \
        virtual RTI_UNIQUE_PTR<Interval> makeLogicalTimeInterval(Value value); \
        RTI_UNIQUE_PTR<LogicalTimeInterval> makeZero() override;           \
        RTI_UNIQUE_PTR<LogicalTimeInterval> makeEpsilon() override;        \
        RTI_UNIQUE_PTR<LogicalTime> decodeLogicalTime(VariableLengthData const& encoded) override; \
        RTI_UNIQUE_PTR<LogicalTime> decodeLogicalTime(void* buffer, size_t bufferSize) override; \
        RTI_UNIQUE_PTR<LogicalTimeInterval> decodeLogicalTimeInterval(VariableLengthData const& encoded) override; \
        RTI_UNIQUE_PTR<LogicalTimeInterval> decodeLogicalTimeInterval(void* buffer, size_t bufferSize) override; \
        std::wstring getName() const override;                             \
    };

#define RTI1516E_TIME_TYPE(Prefix, Value)                                  \
    class Prefix##Interval;                                                \
    RTI1516E_TIME_VALUE_CLASS(Prefix##Time, LogicalTime, Value, getTime, setTime, setInitial, isInitial, setFinal, \
                              isFinal, friend class Prefix##Interval;)     \
    RTI1516E_TIME_VALUE_CLASS(Prefix##Interval, LogicalTimeInterval, Value, getInterval, setInterval, setZero,   \
                              isZero, setEpsilon, isEpsilon,               \
                              void setToDifference(LogicalTime const& minuend, LogicalTime const& subtrahend) override;) \
    RTI1516E_TIME_FACTORY_CLASS(Prefix##TimeFactory, Prefix##Time, Prefix##Interval, Value)

namespace rti1516e {
RTI1516E_TIME_TYPE(HLAfloat64, double)
RTI1516E_TIME_TYPE(HLAinteger64, Integer64)
}  // namespace rti1516e

#endif
