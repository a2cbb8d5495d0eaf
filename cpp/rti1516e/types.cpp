// The API's value types: the exceptions, variable-length data, the handles, the abstract bases' destructors,
// and the factory; the core's errors translated into the standard's exceptions.
#include <RTI/NullFederateAmbassador.h>
#include <RTI/RTI1516.h>
#include <RTI/RTIambassadorFactory.h>

#include <codecvt>
#include <cstring>
#include <locale>
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

std::string utf8(std::wstring const& text) {
    std::wstring_convert<std::codecvt_utf8<wchar_t>> convert;
    try {
        return convert.to_bytes(text);
    } catch (const std::range_error&) {
        throw api::RTIinternalError(L"RTIinternalError: a name that is not Unicode");
    }
}

std::wstring wide(std::string const& text) {
    std::wstring_convert<std::codecvt_utf8<wchar_t>> convert;
    try {
        return convert.from_bytes(text);
    } catch (const std::range_error&) {  // not UTF-8: each byte as its code point (Latin-1)
        return std::wstring(text.begin(), text.end());
    }
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
