// The API's value types: the exceptions, variable-length data, the handles, the abstract bases' destructors,
// and the factory; the core's errors translated into the standard's exceptions.
#include <RTI/NullFederateAmbassador.h>
#include <RTI/RTI1516.h>
#include <RTI/RTIambassadorFactory.h>

#include <cstdint>
#include <cstring>
#include <new>
#include <ostream>
#include <sstream>

#include "ambassador.hpp"
#include "encoding/Octets.h"

namespace api = ::rti1516e;

// ---- exceptions ----

api::Exception::~Exception() = default;

std::wostream& api::operator<<(std::wostream& stream, Exception const& e) { return stream << e.what(); }

#define HLACORE_X(A)                                                         \
    api::A::A(std::wstring const& message) noexcept : _msg(message) {}       \
    std::wstring api::A::what() const noexcept { return _msg; }
RTI1516E_EXCEPTIONS(HLACORE_X)
#undef HLACORE_X

namespace hlacore::rti1516e {

namespace {
// The core's exceptions that IEEE 1516-2010 names otherwise (hlacore.rti1516e translates by the same table);
// the others keep their names, and those with no 1516-2010 counterpart become RTIinternalError.
#define HLACORE_RENAMED(X) \
    X(AttributeNotKnown, AttributeNotDefined) \
    X(ConcurrentAccessAttempted, CallNotAllowedFromWithinCallback) \
    X(CouldNotOpenFED, CouldNotOpenFDD) \
    X(CouldNotRestore, CouldNotInitiateRestore) \
    X(DimensionNotDefined, InvalidDimensionHandle) \
    X(EnableTimeConstrainedPending, RequestForTimeConstrainedPending) \
    X(EnableTimeConstrainedWasNotPending, NoRequestToEnableTimeConstrainedWasPending) \
    X(EnableTimeRegulationPending, RequestForTimeRegulationPending) \
    X(EnableTimeRegulationWasNotPending, NoRequestToEnableTimeRegulationWasPending) \
    X(ErrorReadingFED, ErrorReadingFDD) \
    X(EventNotKnown, MessageCanNoLongerBeRetracted) \
    X(FederateLoggingServiceCalls, FederateServiceInvocationsAreBeingReportedViaMOM) \
    X(FederateWasNotAskedToReleaseAttribute, AttributeDivestitureWasNotRequested) \
    X(FederationTimeAlreadyPassed, LogicalTimeAlreadyPassed) \
    X(InteractionClassNotKnown, InteractionClassNotRecognized) \
    X(InteractionParameterNotKnown, InteractionParameterNotRecognized) \
    X(InvalidExtents, InvalidRangeBound) \
    X(InvalidFederationTime, InvalidLogicalTime) \
    X(InvalidOrderingHandle, InvalidOrderType) \
    X(InvalidRetractionHandle, InvalidMessageRetractionHandle) \
    X(InvalidTransportationHandle, InvalidTransportationType) \
    X(ObjectAlreadyRegistered, ObjectInstanceNameInUse) \
    X(ObjectNotKnown, ObjectInstanceNotKnown) \
    X(RegionInUse, RegionInUseForUpdateOrSubscription) \
    X(RegionNotKnown, InvalidRegion) \
    X(SpaceNotDefined, InvalidDimensionHandle) \
    X(SynchronizationPointLabelWasNotAnnounced, SynchronizationPointLabelNotAnnounced) \
    X(TimeAdvanceAlreadyInProgress, InTimeAdvancingState) \
    X(TimeAdvanceWasNotInProgress, JoinedFederateIsNotInTimeAdvancingState) \
    X(TimeConstrainedWasNotEnabled, TimeConstrainedIsNotEnabled) \
    X(TimeRegulationWasNotEnabled, TimeRegulationIsNotEnabled) \
    X(GatewayNotResponding, NotConnected)

std::string renamed(std::string const& name) {
#define HLACORE_X(from, to) \
    if (name == #from) return #to;
    HLACORE_RENAMED(HLACORE_X)
#undef HLACORE_X
    return name;
}
}  // namespace

void raise(std::string const& name, std::string const& reason) {
    const std::wstring message = wide(name + ": " + reason);
#define HLACORE_X(A) \
    if (name == #A) throw api::A(message);
    RTI1516E_EXCEPTIONS(HLACORE_X)
#undef HLACORE_X
    throw api::RTIinternalError(wide("RTIinternalError: " + name + ": " + reason));
}

void not_served(std::string const& what, std::string const& why) {
    raise("RTIinternalError", "hlacore does not serve " + what + " yet: " + why);
}

void rethrow_as_1516e() {
    try {
        throw;
    } catch (const RtiError& e) {  // the core's, by name
        raise(renamed(error_name(e.code())), e.what());
    } catch (const std::bad_alloc&) {
        throw api::RTIinternalError(L"RTIinternalError: out of memory");
    } catch (const std::exception& e) {
        raise("RTIinternalError", e.what());
    }  // and one of the API's goes through unchanged
}

// UTF-8 both ways, by hand: std::wstring_convert is deprecated since C++17. A wchar_t holds a code point.
static_assert(sizeof(wchar_t) == 4, "a wchar_t of 32 bits, as on Linux");

namespace {
bool scalar_value(std::uint32_t c) { return c <= 0x10FFFF && (c < 0xD800 || c > 0xDFFF); }

// The code point at `i` (moved past it), or false for bytes that are not UTF-8 (overlong, cut short,
// a surrogate, beyond U+10FFFF).
bool next_code_point(std::string const& text, std::size_t& i, std::uint32_t& c) {
    const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[k]); };
    const std::uint8_t lead = byte(i);
    const int more = lead < 0x80 ? 0 : lead >= 0xF0 ? 3 : lead >= 0xE0 ? 2 : lead >= 0xC0 ? 1 : -1;
    if (more < 0 || lead > 0xF4 || i + more >= text.size()) return false;
    c = more ? lead & (0x3F >> more) : lead;
    for (int k = 1; k <= more; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return false;
        c = c << 6 | (byte(i + k) & 0x3F);
    }
    static constexpr std::uint32_t kLeast[] = {0, 0x80, 0x800, 0x10000};
    i += more + 1;
    return c >= kLeast[more] && scalar_value(c);
}
// Bytes that are not UTF-8, each as its code point.
std::wstring latin1(std::string const& text) {
    std::wstring out;
    for (const char b : text) out += static_cast<wchar_t>(static_cast<unsigned char>(b));
    return out;
}
}  // namespace

std::string utf8(std::wstring const& text) {
    std::string out;
    out.reserve(text.size());
    for (const wchar_t w : text) {
        const auto c = static_cast<std::uint32_t>(w);
        if (!scalar_value(c)) throw api::RTIinternalError(L"RTIinternalError: a name that is not Unicode");
        if (c < 0x80) {
            out += static_cast<char>(c);
            continue;
        }
        const int more = c < 0x800 ? 1 : c < 0x10000 ? 2 : 3;
        out += static_cast<char>(((0xFF00 >> (more + 1)) & 0xFF) | c >> (6 * more));  // 110xxxxx, 1110xxxx, 11110xxx
        for (int k = more - 1; k >= 0; --k) out += static_cast<char>(0x80 | (c >> (6 * k) & 0x3F));
    }
    return out;
}

std::wstring wide(std::string const& text) {
    std::wstring out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        std::uint32_t c = 0;
        if (!next_code_point(text, i, c)) return latin1(text);
        out += static_cast<wchar_t>(c);
    }
    return out;
}

std::string bytes(api::VariableLengthData const& data) {
    return data.size() ? std::string(static_cast<const char*>(data.data()), data.size()) : std::string();
}

}  // namespace hlacore::rti1516e

// ---- variable-length data ----

api::VariableLengthData::VariableLengthData(void const* inData, size_t inSize) { setData(inData, inSize); }

api::VariableLengthData::VariableLengthData(VariableLengthData const& rhs) { setData(rhs._data, rhs._size); }

api::VariableLengthData::~VariableLengthData() { release(); }

api::VariableLengthData& api::VariableLengthData::operator=(VariableLengthData const& rhs) {
    if (this != &rhs) setData(rhs._data, rhs._size);
    return *this;
}

void api::VariableLengthData::setData(void const* inData, size_t inSize) {
    char* copy = inSize ? new char[inSize] : nullptr;
    if (inSize) std::memcpy(copy, inData, inSize);
    takeDataPointer(copy, inSize);
}

void api::VariableLengthData::setDataPointer(void* inData, size_t inSize) {
    release();
    _data = inData;
    _size = inSize;
}

void api::VariableLengthData::takeDataPointer(void* inData, size_t inSize, VariableLengthDataDeleteFunction func) {
    release();
    _data = inData;
    _size = inSize;
    _owned = true;
    _deleter = func;
}

void api::VariableLengthData::release() {
    if (_owned) {
        if (_deleter) _deleter(_data);
        else delete[] static_cast<char*>(_data);
    }
    _data = nullptr;
    _size = 0;
    _owned = false;
    _deleter = nullptr;
}

// ---- handles: 4 bytes big-endian, a retraction handle the sender's 4 then the serial's 8 ----

namespace {
template <class H>
size_t encode_handle(H const& h, bool retraction, unsigned long long value, unsigned long sender, void* buffer,
                     size_t size) {
    const size_t length = h.encodedLength();
    if (size < length) throw api::CouldNotEncode(L"CouldNotEncode: the buffer is too small for the handle");
    if (retraction) {
        hlacore_rti1516e::storeBigEndian(buffer, sender, 4);
        hlacore_rti1516e::storeBigEndian(static_cast<char*>(buffer) + 4, value, 8);
    } else {
        hlacore_rti1516e::storeBigEndian(buffer, value, 4);
    }
    return length;
}
}  // namespace

#define HLACORE_X(Kind)                                                                                         \
    long api::Kind::hash() const { return static_cast<long>(_value * 31 + _sender); }                             \
    size_t api::Kind::encodedLength() const {                                                                   \
        return !_valid ? 0 : std::strcmp(#Kind, "MessageRetractionHandle") == 0 ? 12 : 4;                        \
    }                                                                                                           \
    size_t api::Kind::encode(void* buffer, size_t bufferSize) const {                                           \
        return encode_handle(*this, std::strcmp(#Kind, "MessageRetractionHandle") == 0, _value, _sender, buffer, \
                             bufferSize);                                                                        \
    }                                                                                                           \
    void api::Kind::encode(VariableLengthData& buffer) const { buffer = encode(); }                             \
    api::VariableLengthData api::Kind::encode() const {                                                         \
        unsigned char out[12];                                                                                  \
        return VariableLengthData(out, encode(out, sizeof out));                                                \
    }                                                                                                           \
    std::wstring api::Kind::toString() const {                                                                  \
        std::wostringstream s;                                                                                  \
        s << L"" #Kind L"(";                                                                                    \
        if (!_valid) s << L"invalid";                                                                           \
        else if (_sender) s << _sender << L"," << _value;                                                       \
        else s << _value;                                                                                       \
        s << L")";                                                                                              \
        return s.str();                                                                                         \
    }                                                                                                           \
    std::wostream& api::operator<<(std::wostream& stream, Kind const& handle) { return stream << handle.toString(); }
RTI1516E_HANDLE_KINDS(HLACORE_X)
#undef HLACORE_X

// ---- the RTI's name, the abstract bases and the factory ----

std::wstring api::rtiName() { return L"hlacore"; }
std::wstring api::rtiVersion() { return hlacore::rti1516e::wide("IEEE 1516.1-2010, hlacore " HLACORE_VERSION); }

api::RTIambassador::~RTIambassador() = default;
api::FederateAmbassador::~FederateAmbassador() = default;
api::NullFederateAmbassador::~NullFederateAmbassador() = default;
api::RTIambassadorFactory::~RTIambassadorFactory() = default;

RTI_UNIQUE_PTR<api::RTIambassador> api::RTIambassadorFactory::createRTIambassador() {
    return RTI_UNIQUE_PTR<RTIambassador>(new hlacore::rti1516e::Ambassador());
}
