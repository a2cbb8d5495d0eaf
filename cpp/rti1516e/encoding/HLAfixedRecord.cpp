// HLAfixedRecord: its fields in order, each padded to its octet boundary counted from the record's start.
#include <RTI/encoding/HLAfixedRecord.h>

#include "ElementList.h"

namespace rti1516e {

class HLAfixedRecordImplementation : public hlacore_rti1516e::ElementList {
    using ElementList::ElementList;
};

HLAfixedRecord::HLAfixedRecord() : _impl(new HLAfixedRecordImplementation()) {}
HLACORE_COMPOSITE_MEMBERS(HLAfixedRecord)
void HLAfixedRecord::encodeInto(std::vector<Octet>& buffer) const { _impl->encodeInto(buffer, buffer.size()); }
size_t HLAfixedRecord::decodeFrom(std::vector<Octet> const& buffer, size_t index) {
    return _impl->decodeFrom(buffer, index, index);
}
size_t HLAfixedRecord::getEncodedLength() const { return _impl->end(0); }
unsigned int HLAfixedRecord::getOctetBoundary() const { return _impl->boundary(1); }

bool HLAfixedRecord::isSameTypeAs(DataElement const& inData) const {
    if (!DataElement::isSameTypeAs(inData)) return false;
    auto const& other = dynamic_cast<HLAfixedRecord const&>(inData);
    if (other.size() != size()) return false;
    for (size_t i = 0; i < size(); ++i)
        if (!hasElementSameTypeAs(i, other.get(i))) return false;
    return true;
}

bool HLAfixedRecord::hasElementSameTypeAs(size_t index, DataElement const& inData) const {
    return index < size() && get(index).isSameTypeAs(inData);
}

size_t HLAfixedRecord::size() const { return _impl->size(); }
void HLAfixedRecord::appendElement(DataElement const& dataElement) { _impl->append(dataElement); }
void HLAfixedRecord::appendElementPointer(DataElement* dataElement) { _impl->appendPointer(dataElement); }

void HLAfixedRecord::set(size_t index, DataElement const& dataElement) {
    if (!hasElementSameTypeAs(index, dataElement)) hlacore_rti1516e::fail(L"no field of that type at that index");
    _impl->set(index, dataElement);
}
void HLAfixedRecord::setElementPointer(size_t index, DataElement* dataElement) {
    if (dataElement && !hasElementSameTypeAs(index, *dataElement))
        hlacore_rti1516e::fail(L"no field of that type at that index");
    _impl->setPointer(index, dataElement);
}
DataElement const& HLAfixedRecord::get(size_t index) const { return _impl->get(index); }
DataElement const& HLAfixedRecord::operator[](size_t index) const { return get(index); }

}  // namespace rti1516e
