// IEEE 1516.2-2010's fixed array: a set number of elements of the prototype's type, each padded to its octet
// boundary. Elements are copies the array owns, or the caller's (setElementPointer: they must outlive it).
#ifndef RTI_HLAfixedArray_h
#define RTI_HLAfixedArray_h

#include <RTI/SpecificConfig.h>
#include <RTI/encoding/DataElement.h>
#include <RTI/encoding/EncodingConfig.h>

#include <memory>

namespace rti1516e {

class HLAfixedArrayImplementation;

class RTI_EXPORT HLAfixedArray : public DataElement {
public:
    explicit HLAfixedArray(DataElement const& protoType, size_t length);
    HLAfixedArray(HLAfixedArray const& rhs);
    ~HLAfixedArray() override;
    RTI_UNIQUE_PTR<DataElement> clone() const override;
    VariableLengthData encode() const override;
    void encode(VariableLengthData& inData) const override;
    void encodeInto(std::vector<Octet>& buffer) const override;
    void decode(VariableLengthData const& inData) override;
    size_t decodeFrom(std::vector<Octet> const& buffer, size_t index) override;
    size_t getEncodedLength() const override;
    unsigned int getOctetBoundary() const override;
    bool isSameTypeAs(DataElement const& inData) const override;
    virtual bool hasPrototypeSameTypeAs(DataElement const& dataElement) const;
    virtual size_t size() const;
    // These throw EncoderException for an index out of range or an element not of the prototype's type.
    virtual void set(size_t index, DataElement const& dataElement);
    virtual void setElementPointer(size_t index, DataElement* dataElement);
    virtual DataElement const& get(size_t index) const;
    DataElement const& operator[](size_t index) const;

    HLAfixedArray() = delete;
    HLAfixedArray& operator=(HLAfixedArray const& rhs) = delete;

protected:
    std::unique_ptr<HLAfixedArrayImplementation> _impl;
};

}  // namespace rti1516e

#endif
