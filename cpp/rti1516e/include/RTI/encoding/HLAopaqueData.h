// IEEE 1516.2-2010's HLAopaqueData: an HLAinteger32BE byte count, then the bytes. It holds a copy of its
// own, or works in the caller's buffer (the Octet** calls: it must outlive the element), which set and decode
// write while what they write fits; past that the element takes a copy of its own.
#ifndef RTI_HLAopaqueData_h
#define RTI_HLAopaqueData_h

#include <RTI/SpecificConfig.h>
#include <RTI/encoding/DataElement.h>
#include <RTI/encoding/EncodingConfig.h>

#include <vector>

namespace rti1516e {

class RTI_EXPORT HLAopaqueData : public DataElement {
public:
    HLAopaqueData();
    HLAopaqueData(Octet const* inData, size_t dataSize);
    // EncoderException if dataSize is more than bufferSize or the buffer is null.
    HLAopaqueData(Octet** inData, size_t bufferSize, size_t dataSize);
    RTI_DATA_ELEMENT_MEMBERS(HLAopaqueData)
    virtual size_t bufferLength() const;
    virtual size_t dataLength() const;
    virtual void setDataPointer(Octet** inData, size_t bufferSize, size_t dataSize);
    virtual void set(Octet const* inData, size_t dataSize);
    virtual Octet const* get() const;
    operator Octet const*() const;

    HLAopaqueData& operator=(HLAopaqueData const& rhs) = delete;

private:
    void store(Octet const* inData, size_t dataSize);

    std::vector<Octet> _own;
    Octet* _buffer = nullptr;  // the caller's buffer, or null for _own
    size_t _bufferSize = 0;
    size_t _dataSize = 0;
};

}  // namespace rti1516e

#endif
