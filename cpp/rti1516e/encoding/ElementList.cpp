// The members of an array or a fixed record (ElementList.h).
#include "ElementList.h"

#include <algorithm>

namespace hlacore_rti1516e {

ElementList::ElementList(ElementList const& other) {
    for (auto const& s : other._slots) append(*s.element);
}

void ElementList::append(DataElement const& element) {
    auto copy = element.clone();
    DataElement* pointer = copy.get();
    _slots.push_back(Slot{std::move(copy), pointer});
}

void ElementList::appendPointer(DataElement* element) {
    if (!element) fail(L"null element pointer");
    _slots.push_back(Slot{nullptr, element});
}

ElementList::Slot& ElementList::slot(size_t index) {
    if (index >= _slots.size())
        fail(L"index " + std::to_wstring(index) + L" out of range (size " + std::to_wstring(_slots.size()) + L")");
    return _slots[index];
}

void ElementList::set(size_t index, DataElement const& element) {
    Slot& s = slot(index);
    s.own = element.clone();
    s.element = s.own.get();
}

void ElementList::setPointer(size_t index, DataElement* element) {
    if (!element) fail(L"null element pointer");
    Slot& s = slot(index);
    s.own.reset();
    s.element = element;
}

DataElement const& ElementList::get(size_t index) const {
    return *const_cast<ElementList*>(this)->slot(index).element;
}

void ElementList::resize(size_t count, DataElement const& prototype) {
    if (count < _slots.size()) _slots.resize(count);
    while (_slots.size() < count) append(prototype);
}

void ElementList::encodeInto(Octets& buffer, size_t start) const {
    for (auto const& s : _slots) encodePadded(*s.element, buffer, start);
}

size_t ElementList::decodeFrom(Octets const& buffer, size_t index, size_t start) {
    for (auto& s : _slots) index = decodePadded(*s.element, buffer, index, start);
    return index;
}

size_t ElementList::end(size_t position) const {
    for (auto const& s : _slots) position = paddedEnd(*s.element, position);
    return position;
}

unsigned ElementList::boundary(unsigned least) const {
    for (auto const& s : _slots) least = std::max(least, s.element->getOctetBoundary());
    return least;
}

Array::Array(DataElement const& prototype, size_t count) : prototype(prototype.clone()) {
    elements.resize(count, prototype);
}

Array::Array(Array const& other) : prototype(other.prototype->clone()), elements(other.elements) {}

void Array::check(DataElement const& element) const {
    if (!prototype->isSameTypeAs(element)) fail(L"element not of the array's prototype type");
}

void Array::set(size_t index, DataElement const& element) {
    check(element);
    elements.set(index, element);
}

void Array::setPointer(size_t index, DataElement* element) {
    if (element) check(*element);
    elements.setPointer(index, element);
}

bool Array::isSameTypeAs(Array const& other) const { return prototype->isSameTypeAs(*other.prototype); }

}  // namespace hlacore_rti1516e
