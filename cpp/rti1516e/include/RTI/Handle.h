// The handles of IEEE 1516.1-2010's C++ API: values that compare, order, hash and encode. A handle built
// empty is not valid; the RTIambassador makes the valid ones (and decodes them with its decode<Kind>Handle).
// The encoding is 4 bytes big-endian (a message retraction handle: the sending federate's 4, then the serial's
// 8), the same as hlacore.rti1516e's.
#ifndef RTI_Handle_h
#define RTI_Handle_h

#include <RTI/Exception.h>
#include <RTI/SpecificConfig.h>
#include <RTI/VariableLengthData.h>

#include <iosfwd>
#include <string>

#define RTI1516E_HANDLE_KINDS(X)                                                                              \
    X(FederateHandle) X(ObjectClassHandle) X(InteractionClassHandle) X(ObjectInstanceHandle) X(AttributeHandle) \
    X(ParameterHandle) X(DimensionHandle) X(MessageRetractionHandle) X(RegionHandle)

#define DEFINE_HANDLE_CLASS(HandleKind)                                         \
    class HandleKind##Friend;                                                   \
    class RTI_EXPORT HandleKind {                                               \
    public:                                                                     \
        HandleKind() = default;                                                 \
        bool isValid() const { return _valid; }                                 \
        bool operator==(HandleKind const& rhs) const {                          \
            return _valid == rhs._valid && _value == rhs._value && _sender == rhs._sender; \
        }                                                                       \
        bool operator!=(HandleKind const& rhs) const { return !(*this == rhs); } \
        bool operator<(HandleKind const& rhs) const {                           \
            if (_valid != rhs._valid) return !_valid;                           \
            return _sender != rhs._sender ? _sender < rhs._sender : _value < rhs._value; \
        }                                                                       \
        long hash() const;                                                      \
        VariableLengthData encode() const;                                      \
        void encode(VariableLengthData& buffer) const;                          \
        size_t encode(void* buffer, size_t bufferSize) const;                   \
        size_t encodedLength() const;                                           \
        std::wstring toString() const;                                          \
                                                                                \
    private:                                                                    \
        friend class HandleKind##Friend;                                        \
        unsigned long long _value = 0;                                          \
        unsigned long _sender = 0; /* a message retraction handle's federate */ \
        bool _valid = false;                                                    \
    };                                                                          \
    RTI_EXPORT std::wostream& operator<<(std::wostream& stream, HandleKind const& handle);

namespace rti1516e {
RTI1516E_HANDLE_KINDS(DEFINE_HANDLE_CLASS)
}  // namespace rti1516e

#endif
