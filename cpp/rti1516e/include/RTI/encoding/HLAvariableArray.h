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
    // decode keeps the elements it has (the caller's too) up to the decoded count, adds copies of the prototype.
    RTI_DATA_ELEMENT_MEMBERS(HLAvariableArray)
    virtual bool hasPrototypeSameTypeAs(DataElement const& dataElement) const;
    // These throw EncoderException for an index out of range or an element not of the prototype's type.
    virtual void addElement(DataElement const& dataElement);
    virtual void addElementPointer(DataElement* dataElement);
    RTI_ELEMENT_LIST_MEMBERS

    HLAvariableArray() = delete;
    RTI_COMPOSITE_IMPLEMENTATION(HLAvariableArray)
};

}  // namespace rti1516e

#endif
