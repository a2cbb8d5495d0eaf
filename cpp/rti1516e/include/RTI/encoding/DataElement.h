// What every encoding helper is: a value that encodes itself to IEEE 1516.2-2010 bytes and decodes itself back.
// Composites (arrays, records) pad each member to its octet boundary, counted from their own start.
#ifndef RTI_DataElement_h
#define RTI_DataElement_h

#include <RTI/SpecificConfig.h>
#include <RTI/encoding/EncodingConfig.h>
#include <RTI/encoding/EncodingExceptions.h>

#include <memory>
#include <vector>

namespace rti1516e {

class VariableLengthData;

class RTI_EXPORT DataElement {
public:
    virtual ~DataElement() = 0;
    virtual RTI_UNIQUE_PTR<DataElement> clone() const = 0;
    virtual VariableLengthData encode() const = 0;
    virtual void encode(VariableLengthData& inData) const = 0;
    // Appends the encoding to buffer.
    virtual void encodeInto(std::vector<Octet>& buffer) const = 0;
    // Decodes all of inData: bytes left over are an error.
    virtual void decode(VariableLengthData const& inData) = 0;
    // Decodes from buffer[index]; returns the index after the value.
    virtual size_t decodeFrom(std::vector<Octet> const& buffer, size_t index) = 0;
    virtual size_t getEncodedLength() const = 0;
    virtual unsigned int getOctetBoundary() const = 0;
    // By default: the same class.
    virtual bool isSameTypeAs(DataElement const& inData) const;
    // By default: a hash of the encoding (a variant record's discriminants are told apart by it).
    virtual Integer64 hash() const;
};

// What each concrete element declares of DataElement: its copy, its encoding and decoding, its octet boundary.
#define RTI_DATA_ELEMENT_MEMBERS(Class)                                        \
    Class(Class const& rhs);                                                   \
    ~Class() override;                                                         \
    RTI_UNIQUE_PTR<DataElement> clone() const override;                        \
    VariableLengthData encode() const override;                                \
    void encode(VariableLengthData& inData) const override;                    \
    void encodeInto(std::vector<Octet>& buffer) const override;                \
    void decode(VariableLengthData const& inData) override;                    \
    size_t decodeFrom(std::vector<Octet> const& buffer, size_t index) override; \
    size_t getEncodedLength() const override;                                  \
    unsigned int getOctetBoundary() const override;

// What the arrays and the fixed record declare of their members, by index; these throw EncoderException for an
// index out of range or an element not of the type wanted there.
#define RTI_ELEMENT_LIST_MEMBERS                                                \
    virtual size_t size() const;                                               \
    virtual void set(size_t index, DataElement const& dataElement);            \
    virtual void setElementPointer(size_t index, DataElement* dataElement);    \
    virtual DataElement const& get(size_t index) const;                        \
    DataElement const& operator[](size_t index) const;

// A composite's end: its type test (its members' types too), it is not assigned (its members may be the
// caller's), and it holds its implementation.
#define RTI_COMPOSITE_IMPLEMENTATION(Class)                                     \
    bool isSameTypeAs(DataElement const& inData) const override;               \
    Class& operator=(Class const& rhs) = delete;                               \
                                                                               \
protected:                                                                     \
    std::unique_ptr<Class##Implementation> _impl;

}  // namespace rti1516e

#endif
