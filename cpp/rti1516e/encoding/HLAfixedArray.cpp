// HLAfixedArray: its elements one after another, each padded to its octet boundary; no count.
#include <RTI/encoding/HLAfixedArray.h>

#include "ElementList.h"

namespace rti1516e {

class HLAfixedArrayImplementation : public hlacore_rti1516e::Array {
    using Array::Array;
};

HLAfixedArray::HLAfixedArray(DataElement const& protoType, size_t length)
    : _impl(new HLAfixedArrayImplementation(protoType, length)) {}
HLACORE_COMPOSITE_MEMBERS(HLAfixedArray)
void HLAfixedArray::encodeInto(std::vector<Octet>& buffer) const { _impl->elements.encodeInto(buffer, buffer.size()); }
size_t HLAfixedArray::decodeFrom(std::vector<Octet> const& buffer, size_t index) {
    return _impl->elements.decodeFrom(buffer, index, index);
}
size_t HLAfixedArray::getEncodedLength() const { return _impl->elements.end(0); }
unsigned int HLAfixedArray::getOctetBoundary() const {
    return _impl->elements.boundary(_impl->prototype->getOctetBoundary());
}

bool HLAfixedArray::isSameTypeAs(DataElement const& inData) const {
    auto const* other = dynamic_cast<HLAfixedArray const*>(&inData);
    return DataElement::isSameTypeAs(inData) && _impl->isSameTypeAs(*other->_impl) && size() == other->size();
}
bool HLAfixedArray::hasPrototypeSameTypeAs(DataElement const& dataElement) const {
    return _impl->prototype->isSameTypeAs(dataElement);
}

size_t HLAfixedArray::size() const { return _impl->elements.size(); }
void HLAfixedArray::set(size_t index, DataElement const& dataElement) { _impl->set(index, dataElement); }
void HLAfixedArray::setElementPointer(size_t index, DataElement* dataElement) { _impl->setPointer(index, dataElement); }
DataElement const& HLAfixedArray::get(size_t index) const { return _impl->elements.get(index); }
DataElement const& HLAfixedArray::operator[](size_t index) const { return get(index); }

}  // namespace rti1516e
