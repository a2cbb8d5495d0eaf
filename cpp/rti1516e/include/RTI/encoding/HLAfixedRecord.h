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
    RTI_DATA_ELEMENT_MEMBERS(HLAfixedRecord)
    virtual bool hasElementSameTypeAs(size_t index, DataElement const& inData) const;
    virtual void appendElement(DataElement const& dataElement);
    virtual void appendElementPointer(DataElement* dataElement);
    RTI_ELEMENT_LIST_MEMBERS

    RTI_COMPOSITE_IMPLEMENTATION(HLAfixedRecord)
};

}  // namespace rti1516e

#endif
