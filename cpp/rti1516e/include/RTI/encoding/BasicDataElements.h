// The basic data types of IEEE 1516.2-2010 as encoding helpers, one class per type, all of one shape: each
// holds its value, or refers to the caller's variable (the pointer constructor, setDataPointer), which set and
// decode then write and get and encode read. A copy or clone always holds its own value.
#ifndef RTI_BasicDataElements_h
#define RTI_BasicDataElements_h

#include <RTI/SpecificConfig.h>
#include <RTI/encoding/DataElement.h>
#include <RTI/encoding/EncodingConfig.h>

#include <string>

namespace rti1516e {

#define RTI1516E_BASIC_DATA_ELEMENT(Name, Value)                                      \
    class RTI_EXPORT Name : public DataElement {                                      \
    public:                                                                           \
        Name();                                                                       \
        explicit Name(Value const& inData);                                           \
        /* Null: the element holds its own value. */                                  \
        explicit Name(Value* inData);                                                 \
        RTI_DATA_ELEMENT_MEMBERS(Name)                                                \
        /* Copies the value, into the caller's variable if it refers to one. */       \
        Name& operator=(Name const& rhs);                                             \
        Integer64 hash() const override;                                              \
        /* Null throws EncoderException. */                                           \
        virtual void setDataPointer(Value* inData);                                   \
        virtual void set(Value inData);                                               \
        virtual Value get() const;                                                    \
        Name& operator=(Value rhs);                                                   \
        operator Value() const;                                                       \
                                                                                      \
    protected:                                                                        \
        Value _value;                                                                 \
        Value* _data; /* &_value, or the caller's variable */                         \
    };

RTI1516E_BASIC_DATA_ELEMENT(HLAASCIIchar, char)
RTI1516E_BASIC_DATA_ELEMENT(HLAASCIIstring, std::string)
RTI1516E_BASIC_DATA_ELEMENT(HLAboolean, bool)
RTI1516E_BASIC_DATA_ELEMENT(HLAbyte, Octet)
RTI1516E_BASIC_DATA_ELEMENT(HLAfloat32BE, float)
RTI1516E_BASIC_DATA_ELEMENT(HLAfloat32LE, float)
RTI1516E_BASIC_DATA_ELEMENT(HLAfloat64BE, double)
RTI1516E_BASIC_DATA_ELEMENT(HLAfloat64LE, double)
RTI1516E_BASIC_DATA_ELEMENT(HLAinteger16BE, Integer16)
RTI1516E_BASIC_DATA_ELEMENT(HLAinteger16LE, Integer16)
RTI1516E_BASIC_DATA_ELEMENT(HLAinteger32BE, Integer32)
RTI1516E_BASIC_DATA_ELEMENT(HLAinteger32LE, Integer32)
RTI1516E_BASIC_DATA_ELEMENT(HLAinteger64BE, Integer64)
RTI1516E_BASIC_DATA_ELEMENT(HLAinteger64LE, Integer64)
RTI1516E_BASIC_DATA_ELEMENT(HLAoctet, Octet)
RTI1516E_BASIC_DATA_ELEMENT(HLAoctetPairBE, OctetPair)
RTI1516E_BASIC_DATA_ELEMENT(HLAoctetPairLE, OctetPair)
// One UTF-16 code unit: a character beyond U+FFFF cannot be encoded.
RTI1516E_BASIC_DATA_ELEMENT(HLAunicodeChar, wchar_t)
// Count of UTF-16 code units, then the units (characters beyond U+FFFF as surrogate pairs).
RTI1516E_BASIC_DATA_ELEMENT(HLAunicodeString, std::wstring)

#undef RTI1516E_BASIC_DATA_ELEMENT

}  // namespace rti1516e

#endif
