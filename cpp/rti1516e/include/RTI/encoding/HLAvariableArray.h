// IEEE 1516.2-2010's variable array: an HLAinteger32BE element count, then the elements (of the prototype's
// type), each padded to its octet boundary counted from the array's start. Elements are copies the array
// owns, or the caller's (addElementPointer, setElementPointer: they must outlive it).
#ifndef RTI_HLAvariableArray_h
#define RTI_HLAvariableArray_h

#include <RTI/SpecificConfig.h>
#include <RTI/encoding/DataElement.h>
#include <RTI/encoding/EncodingConfig.h>

#include <memory>

namespace rti1516e {

class HLAvariableArrayImplementation;

class RTI_EXPORT HLAvariableArray : public DataElement {
public:
    explicit HLAvariableArray(DataElement const& prototype);
    HLAvariableArray(HLAvariableArray const& rhs);
    ~HLAvariableArray() override;
    RTI_UNIQUE_PTR<DataElement> clone() const override;
    VariableLengthData encode() const override;
    void encode(VariableLengthData& inData) const override;
    void encodeInto(std::vector<Octet>& buffer) const override;
    // Keeps the elements it has (the caller's too) up to the decoded count, adds copies of the prototype.
    void decode(VariableLengthData const& inData) override;
    size_t decodeFrom(std::vector<Octet> const& buffer, size_t index) override;
    size_t getEncodedLength() const override;
    unsigned int getOctetBoundary() const override;
    virtual size_t size() const;
    bool isSameTypeAs(DataElement const& inData) const override;
    virtual bool hasPrototypeSameTypeAs(DataElement const& dataElement) const;
    // These throw EncoderException for an index out of range or an element not of the prototype's type.
    virtual void addElement(DataElement const& dataElement);
    virtual void addElementPointer(DataElement* dataElement);
    virtual void set(size_t index, DataElement const& dataElement);
    virtual void setElementPointer(size_t index, DataElement* dataElement);
    virtual DataElement const& get(size_t index) const;
    DataElement const& operator[](size_t index) const;

    HLAvariableArray() = delete;
    HLAvariableArray& operator=(HLAvariableArray const& rhs) = delete;

protected:
    std::unique_ptr<HLAvariableArrayImplementation> _impl;
};

}  // namespace rti1516e

#endif
