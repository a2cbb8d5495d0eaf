// DataElement's defaults: its destructor, the type test (the same class) and the hash (of the encoding).
#include <RTI/encoding/DataElement.h>

#include <cstdint>
#include <typeinfo>

namespace rti1516e {

DataElement::~DataElement() {}

bool DataElement::isSameTypeAs(DataElement const& inData) const { return typeid(*this) == typeid(inData); }

Integer64 DataElement::hash() const {
    std::vector<Octet> bytes;
    encodeInto(bytes);
    std::uint64_t h = 14695981039346656037ull;  // 64-bit FNV-1a
    for (Octet b : bytes) h = (h ^ static_cast<unsigned char>(b)) * 1099511628211ull;
    return static_cast<Integer64>(h);
}

}  // namespace rti1516e
