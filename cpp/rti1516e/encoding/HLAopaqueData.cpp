// HLAopaqueData: an HLAinteger32BE byte count, then the bytes, as a copy of its own or in the caller's buffer.
#include <RTI/encoding/HLAopaqueData.h>

#include <cstring>

#include "Octets.h"

namespace rti1516e {

using hlacore_rti1516e::fail;

HLAopaqueData::HLAopaqueData() {}
HLAopaqueData::HLAopaqueData(Octet const* inData, size_t dataSize) { set(inData, dataSize); }
HLAopaqueData::HLAopaqueData(Octet** inData, size_t bufferSize, size_t dataSize) {
    setDataPointer(inData, bufferSize, dataSize);
}
HLAopaqueData::HLAopaqueData(HLAopaqueData const& rhs) : DataElement() { set(rhs.get(), rhs.dataLength()); }
HLAopaqueData::~HLAopaqueData() {}

RTI_UNIQUE_PTR<DataElement> HLAopaqueData::clone() const { return RTI_UNIQUE_PTR<DataElement>(new HLAopaqueData(*this)); }
HLACORE_WHOLE_ENCODING(HLAopaqueData)

void HLAopaqueData::encodeInto(std::vector<Octet>& buffer) const {
    hlacore_rti1516e::putCount(buffer, _dataSize);
    buffer.insert(buffer.end(), get(), get() + _dataSize);
}

size_t HLAopaqueData::decodeFrom(std::vector<Octet> const& buffer, size_t index) {
    size_t count = hlacore_rti1516e::getCount(buffer, index);
    hlacore_rti1516e::need(buffer, index, count);
    store(buffer.data() + index, count);
    return index + count;
}

size_t HLAopaqueData::getEncodedLength() const { return 4 + _dataSize; }
unsigned int HLAopaqueData::getOctetBoundary() const { return 4; }
size_t HLAopaqueData::bufferLength() const { return _buffer ? _bufferSize : _own.size(); }
size_t HLAopaqueData::dataLength() const { return _dataSize; }

void HLAopaqueData::setDataPointer(Octet** inData, size_t bufferSize, size_t dataSize) {
    if (!inData || !*inData) fail(L"HLAopaqueData: null buffer");
    if (dataSize > bufferSize) fail(L"HLAopaqueData: more data than buffer");
    _buffer = *inData;
    _bufferSize = bufferSize;
    _dataSize = dataSize;
    _own.clear();
}

void HLAopaqueData::set(Octet const* inData, size_t dataSize) { store(inData, dataSize); }
Octet const* HLAopaqueData::get() const { return _buffer ? _buffer : _own.data(); }
HLAopaqueData::operator Octet const*() const { return get(); }

void HLAopaqueData::store(Octet const* inData, size_t dataSize) {
    if (_buffer && dataSize <= _bufferSize) {
        if (dataSize) std::memmove(_buffer, inData, dataSize);
    } else {
        std::vector<Octet> copy(inData, inData + dataSize);  // inData may be in _own
        _own.swap(copy);
        _buffer = nullptr;
    }
    _dataSize = dataSize;
}

}  // namespace rti1516e
