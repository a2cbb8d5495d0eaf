// HLAvariantRecord: the discriminant, then the selected variant's value padded to its octet boundary counted
// from the record's start. A variant is found by its discriminant's encoding.
#include <RTI/encoding/HLAvariantRecord.h>

#include <algorithm>

#include "Octets.h"

namespace rti1516e {

using hlacore_rti1516e::fail;
using hlacore_rti1516e::Octets;

class HLAvariantRecordImplementation {
public:
    struct Variant {
        Octets key;  // the discriminant's encoding
        std::unique_ptr<DataElement> own;
        DataElement* value;  // own, or the caller's
    };

    explicit HLAvariantRecordImplementation(DataElement const& prototype) : discriminant(prototype.clone()) {}
    // A copy owns its values, the caller's too.
    HLAvariantRecordImplementation(HLAvariantRecordImplementation const& other)
        : discriminant(other.discriminant->clone()) {
        for (auto const& v : other.variants) add(v.key, v.value->clone(), nullptr);
    }

    Octets keyOf(DataElement const& d) const {
        if (!discriminant->isSameTypeAs(d)) fail(L"discriminant not of the record's discriminant type");
        Octets key;
        d.encodeInto(key);
        return key;
    }

    Variant* find(Octets const& key) {
        auto it = std::find_if(variants.begin(), variants.end(), [&](Variant const& v) { return v.key == key; });
        return it == variants.end() ? nullptr : &*it;
    }

    Variant& existing(DataElement const& d) {
        Variant* v = find(keyOf(d));
        if (!v) fail(L"no variant for that discriminant");
        return *v;
    }

    void add(Octets key, std::unique_ptr<DataElement> own, DataElement* value) {
        if (find(key)) fail(L"a variant for that discriminant exists");
        if (own) value = own.get();
        if (!value) fail(L"null variant pointer");
        variants.push_back(Variant{std::move(key), std::move(own), value});
    }

    // The variant the current discriminant selects.
    Variant& current() {
        Octets key;
        discriminant->encodeInto(key);
        Variant* v = find(key);
        if (!v) fail(L"no variant for the discriminant");
        return *v;
    }

    std::unique_ptr<DataElement> discriminant;
    std::vector<Variant> variants;
};

HLAvariantRecord::HLAvariantRecord(DataElement const& discriminantPrototype)
    : _impl(new HLAvariantRecordImplementation(discriminantPrototype)) {}
HLACORE_COMPOSITE_MEMBERS(HLAvariantRecord)

void HLAvariantRecord::encodeInto(std::vector<Octet>& buffer) const {
    size_t start = buffer.size();
    DataElement const& value = getVariant();
    _impl->discriminant->encodeInto(buffer);
    hlacore_rti1516e::encodePadded(value, buffer, start);
}

size_t HLAvariantRecord::decodeFrom(std::vector<Octet> const& buffer, size_t index) {
    auto decoded = _impl->discriminant->clone();
    size_t end = decoded->decodeFrom(buffer, index);
    auto& variant = _impl->existing(*decoded);
    end = hlacore_rti1516e::decodePadded(*variant.value, buffer, end, index);
    _impl->discriminant = std::move(decoded);
    return end;
}

size_t HLAvariantRecord::getEncodedLength() const {
    return hlacore_rti1516e::paddedEnd(getVariant(), _impl->discriminant->getEncodedLength());
}

unsigned int HLAvariantRecord::getOctetBoundary() const {
    unsigned boundary = _impl->discriminant->getOctetBoundary();
    for (auto const& v : _impl->variants) boundary = std::max(boundary, v.value->getOctetBoundary());
    return boundary;
}

bool HLAvariantRecord::isSameTypeAs(DataElement const& inData) const {
    if (!DataElement::isSameTypeAs(inData)) return false;
    auto const& other = *dynamic_cast<HLAvariantRecord const&>(inData)._impl;
    if (!_impl->discriminant->isSameTypeAs(*other.discriminant) || other.variants.size() != _impl->variants.size())
        return false;
    for (auto& v : other.variants) {
        auto* mine = _impl->find(v.key);
        if (!mine || !mine->value->isSameTypeAs(*v.value)) return false;
    }
    return true;
}

bool HLAvariantRecord::isSameTypeAs(DataElement const& discriminant, DataElement const& inData) const {
    return _impl->existing(discriminant).value->isSameTypeAs(inData);
}

bool HLAvariantRecord::hasMatchingDiscriminantTypeAs(DataElement const& dataElement) const {
    return _impl->discriminant->isSameTypeAs(dataElement);
}

void HLAvariantRecord::addVariant(DataElement const& discriminant, DataElement const& valuePrototype) {
    _impl->add(_impl->keyOf(discriminant), valuePrototype.clone(), nullptr);
}

void HLAvariantRecord::addVariantPointer(DataElement const& discriminant, DataElement* valuePtr) {
    _impl->add(_impl->keyOf(discriminant), nullptr, valuePtr);
}

void HLAvariantRecord::setDiscriminant(DataElement const& discriminant) {
    _impl->keyOf(discriminant);
    _impl->discriminant = discriminant.clone();
}

void HLAvariantRecord::setVariant(DataElement const& discriminant, DataElement const& value) {
    auto& variant = _impl->existing(discriminant);
    if (!variant.value->isSameTypeAs(value)) fail(L"value not of its variant's type");
    variant.own = value.clone();
    variant.value = variant.own.get();
    _impl->discriminant = discriminant.clone();
}

void HLAvariantRecord::setVariantPointer(DataElement const& discriminant, DataElement* valuePtr) {
    auto& variant = _impl->existing(discriminant);
    if (!valuePtr) fail(L"null variant pointer");
    if (!variant.value->isSameTypeAs(*valuePtr)) fail(L"value not of its variant's type");
    variant.own.reset();
    variant.value = valuePtr;
    _impl->discriminant = discriminant.clone();
}

DataElement const& HLAvariantRecord::getDiscriminant() const { return *_impl->discriminant; }
DataElement const& HLAvariantRecord::getVariant() const { return *_impl->current().value; }

}  // namespace rti1516e
