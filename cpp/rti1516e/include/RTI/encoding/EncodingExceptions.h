// The one exception the encoding helpers raise: a value that cannot be encoded, bytes that cannot be decoded,
// an element of the wrong type, an index out of range.
#ifndef RTI_EncodingExceptions_h
#define RTI_EncodingExceptions_h

#include <RTI/Exception.h>
#include <RTI/SpecificConfig.h>
#include <RTI/encoding/EncodingConfig.h>

#include <string>

namespace rti1516e {

class RTI_EXPORT EncoderException : public Exception {
public:
    EncoderException(std::wstring const& message) noexcept;
    std::wstring what() const noexcept override;

private:
    std::wstring _msg;
};

}  // namespace rti1516e

#endif
