// EncoderException: the encoding helpers' one exception.
#include <RTI/encoding/EncodingExceptions.h>

namespace rti1516e {

EncoderException::EncoderException(std::wstring const& message) noexcept : _msg(message) {}
std::wstring EncoderException::what() const noexcept { return _msg; }

}  // namespace rti1516e
