// HLAvariableArray: an HLAinteger32BE count, then the elements, each padded to its octet boundary counted from
// the array's start (so the first of an 8-byte type follows 4 pad bytes).
#include <RTI/encoding/HLAvariableArray.h>

#include <algorithm>

#include "ElementList.h"

namespace rti1516e {

class HLAvariableArrayImplementation : public hlacore_rti1516e::Array {
    using Array::Array;
};

HLAvariableArray::HLAvariableArray(DataElement const& prototype) : _impl(new HLAvariableArrayImplementation(prototype, 0)) {}
HLACORE_COMPOSITE_MEMBERS(HLAvariableArray)

void HLAvariableArray::encodeInto(std::vector<Octet>& buffer) const {
    size_t start = buffer.size();
    hlacore_rti1516e::putCount(buffer, size());
    _impl->elements.encodeInto(buffer, start);
}

size_t HLAvariableArray::decodeFrom(std::vector<Octet> const& buffer, size_t index) {
    size_t start = index;
    size_t count = hlacore_rti1516e::getCount(buffer, index);
    // Each element takes a byte at least (an empty record, none: then the count is only bounded by memory).
    if (_impl->prototype->getEncodedLength() > 0) hlacore_rti1516e::need(buffer, index, count);
    _impl->elements.resize(count, *_impl->prototype);
    return _impl->elements.decodeFrom(buffer, index, start);
}

size_t HLAvariableArray::getEncodedLength() const { return _impl->elements.end(4); }
unsigned int HLAvariableArray::getOctetBoundary() const {
    return _impl->elements.boundary(std::max(4u, _impl->prototype->getOctetBoundary()));
}

size_t HLAvariableArray::size() const { return _impl->elements.size(); }
bool HLAvariableArray::isSameTypeAs(DataElement const& inData) const {
    return DataElement::isSameTypeAs(inData) &&
           _impl->isSameTypeAs(*dynamic_cast<HLAvariableArray const&>(inData)._impl);
}
bool HLAvariableArray::hasPrototypeSameTypeAs(DataElement const& dataElement) const {
    return _impl->prototype->isSameTypeAs(dataElement);
}

void HLAvariableArray::addElement(DataElement const& dataElement) {
    _impl->check(dataElement);
    _impl->elements.append(dataElement);
}
void HLAvariableArray::addElementPointer(DataElement* dataElement) {
    if (dataElement) _impl->check(*dataElement);
    _impl->elements.appendPointer(dataElement);
}
void HLAvariableArray::set(size_t index, DataElement const& dataElement) { _impl->set(index, dataElement); }
void HLAvariableArray::setElementPointer(size_t index, DataElement* dataElement) {
    _impl->setPointer(index, dataElement);
}
DataElement const& HLAvariableArray::get(size_t index) const { return _impl->elements.get(index); }
DataElement const& HLAvariableArray::operator[](size_t index) const { return get(index); }

}  // namespace rti1516e
