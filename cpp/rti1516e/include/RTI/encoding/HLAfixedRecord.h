// IEEE 1516.2-2010's fixed record: its fields in order, each padded to its octet boundary counted from the
// record's start. Fields are copies the record owns, or the caller's (the *Pointer calls: they must outlive it).
#ifndef RTI_HLAfixedRecord_h
#define RTI_HLAfixedRecord_h

#include <RTI/SpecificConfig.h>
#include <RTI/encoding/DataElement.h>
#include <RTI/encoding/EncodingConfig.h>

#include <memory>

namespace rti1516e {

class HLAfixedRecordImplementation;

class RTI_EXPORT HLAfixedRecord : public DataElement {
public:
    HLAfixedRecord();
    HLAfixedRecord(HLAfixedRecord const& rhs);
    ~HLAfixedRecord() override;
    RTI_UNIQUE_PTR<DataElement> clone() const override;
    VariableLengthData encode() const override;
    void encode(VariableLengthData& inData) const override;
    void encodeInto(std::vector<Octet>& buffer) const override;
    void decode(VariableLengthData const& inData) override;
    size_t decodeFrom(std::vector<Octet> const& buffer, size_t index) override;
    size_t getEncodedLength() const override;
    unsigned int getOctetBoundary() const override;
    bool isSameTypeAs(DataElement const& inData) const override;
    virtual bool hasElementSameTypeAs(size_t index, DataElement const& inData) const;
    virtual size_t size() const;
    virtual void appendElement(DataElement const& dataElement);
    virtual void appendElementPointer(DataElement* dataElement);
    // These throw EncoderException for an index out of range or a field of another type than the one there.
    virtual void set(size_t index, DataElement const& dataElement);
    virtual void setElementPointer(size_t index, DataElement* dataElement);
    virtual DataElement const& get(size_t index) const;
    DataElement const& operator[](size_t index) const;

    HLAfixedRecord& operator=(HLAfixedRecord const& rhs) = delete;

protected:
    std::unique_ptr<HLAfixedRecordImplementation> _impl;
};

}  // namespace rti1516e

#endif
