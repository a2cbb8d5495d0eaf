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
    RTI_DATA_ELEMENT_MEMBERS(HLAfixedArray)
    virtual bool hasPrototypeSameTypeAs(DataElement const& dataElement) const;
    RTI_ELEMENT_LIST_MEMBERS

    HLAfixedArray() = delete;
    RTI_COMPOSITE_IMPLEMENTATION(HLAfixedArray)
};

}  // namespace rti1516e

#endif
