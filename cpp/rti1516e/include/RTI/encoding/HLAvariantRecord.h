// IEEE 1516.2-2010's variant record: the discriminant, then the value of the variant it selects, padded to
// that value's octet boundary counted from the record's start. Variants are told apart by their
// discriminants' encodings; a discriminant without a variant cannot be encoded or decoded.
#ifndef RTI_HLAvariantRecord_h
#define RTI_HLAvariantRecord_h

#include <RTI/SpecificConfig.h>
#include <RTI/encoding/DataElement.h>
#include <RTI/encoding/EncodingConfig.h>

#include <memory>

namespace rti1516e {

class HLAvariantRecordImplementation;

class RTI_EXPORT HLAvariantRecord : public DataElement {
public:
    explicit HLAvariantRecord(DataElement const& discriminantPrototype);
    RTI_DATA_ELEMENT_MEMBERS(HLAvariantRecord)
    // Whether the variant of discriminant is of inData's type; EncoderException if there is none.
    virtual bool isSameTypeAs(DataElement const& discriminant, DataElement const& inData) const;
    virtual bool hasMatchingDiscriminantTypeAs(DataElement const& dataElement) const;
    // These throw EncoderException for a discriminant not of the prototype's type, a discriminant added twice,
    // a value not of its variant's type, or (setVariant*) a discriminant without a variant.
    virtual void addVariant(DataElement const& discriminant, DataElement const& valuePrototype);
    virtual void addVariantPointer(DataElement const& discriminant, DataElement* valuePtr);
    virtual void setDiscriminant(DataElement const& discriminant);
    virtual void setVariant(DataElement const& discriminant, DataElement const& value);
    virtual void setVariantPointer(DataElement const& discriminant, DataElement* valuePtr);
    virtual DataElement const& getDiscriminant() const;
    virtual DataElement const& getVariant() const;

    HLAvariantRecord() = delete;
    RTI_COMPOSITE_IMPLEMENTATION(HLAvariantRecord)
};

}  // namespace rti1516e

#endif
