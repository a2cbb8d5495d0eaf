// The HLA 1.3 types libRTI-NG implements: the exceptions, the sets and their factories, the regions, and
// the translation of hlacore's errors into HLA 1.3 exceptions.
#include <algorithm>
#include <cstring>
#include <new>
#include <ostream>

#include "ambassador.hpp"
#include "fedtime.hh"

// ---- exceptions ----

namespace {
char* copy_of(const char* reason) {
    if (!reason) return nullptr;
    const std::size_t n = std::strlen(reason) + 1;
    char* copy = new char[n];
    std::memcpy(copy, reason, n);
    return copy;
}
}  // namespace

RTI::Exception::Exception(const char* reason) : _serial(0), _reason(copy_of(reason)), _name("Exception") {}
RTI::Exception::Exception(ULong serial, const char* reason) : _serial(serial), _reason(copy_of(reason)), _name("Exception") {}
RTI::Exception::Exception(const Exception& toCopy)
    : _serial(toCopy._serial), _reason(copy_of(toCopy._reason)), _name(toCopy._name) {}
RTI::Exception::~Exception() { delete[] _reason; }

RTI::Exception& RTI::Exception::operator=(const Exception& toCopy) {
    if (this != &toCopy) {
        char* reason = copy_of(toCopy._reason);
        delete[] _reason;
        _reason = reason;
        _serial = toCopy._serial;
        _name = toCopy._name;
    }
    return *this;
}

const std::string RTI::Exception::displayMe() const {
    return std::string(_name ? _name : "Exception") + ": " + (_reason ? _reason : "");
}

std::ostream& operator<<(std::ostream& os, const RTI::Exception& ex) { return os << ex.displayMe(); }
std::ostream& operator<<(std::ostream& os, const RTI::Exception* ex) { return ex ? os << *ex : os << "(null exception)"; }

namespace hlacore::hla13 {

namespace {
// The HLA 1.3 exceptions by the names of HLACORE_EXCEPTIONS, hlacore's own among them.
struct Exceptions : RTI {
    using GatewayNotResponding = RTIinternalError;
    using AuthenticationFailed = RTIinternalError;
    using SaveNotInProgress = RTIinternalError;
    using RestoreNotInProgress = RTIinternalError;
    using InvalidUpdateRateDesignator = RTIinternalError;
    using InconsistentFDD = RTIinternalError;
};
}  // namespace

void rethrow_as_hla() {
    try {
        throw;
    } catch (const RTI::Exception&) {
        throw;
    } catch (const RtiError& e) {
        // hlacore's own errors (GatewayNotResponding, AuthenticationFailed) are RTIinternalError, named in the reason.
        const std::string reason = base_of(e.code()) == ErrorCode::RTIinternalError
                                       ? std::string(error_name(e.code())) + ": " + e.what()
                                       : std::string(e.what());
        switch (e.code()) {
#define HLACORE_X(name) \
    case ErrorCode::name: throw Exceptions::name(reason.c_str());
            HLACORE_EXCEPTIONS(HLACORE_X)
#undef HLACORE_X
            default: throw RTI::RTIinternalError(reason.c_str());
        }
    } catch (const std::bad_alloc&) {
        throw RTI::MemoryExhausted("out of memory");
    } catch (const std::exception& e) {
        throw RTI::RTIinternalError(e.what());
    }
}

double time_of(const RTI::FedTime& time) {
    return RTIfedTime(time).getTime();  // libFedTime's check: InvalidFederationTime for another type
}

// ---- sets ----

namespace {
[[noreturn]] void out_of_bounds(RTI::ULong index, std::size_t size) {
    throw RTI::ArrayIndexOutOfBounds(
        ("index " + std::to_string(index) + " of a set of " + std::to_string(size)).c_str());
}
}  // namespace

RTI::ULong HandleList::at(RTI::ULong index) const {
    if (index >= handles.size()) out_of_bounds(index, handles.size());
    return handles[index];
}

void HandleList::add(RTI::ULong handle) {
    if (!contains(handle)) handles.push_back(h32(handle));
}

bool HandleList::erase(RTI::ULong handle) {
    const auto it = std::find(handles.begin(), handles.end(), h32(handle));
    if (it == handles.end()) return false;
    handles.erase(it);
    return true;
}

bool HandleList::contains(RTI::ULong handle) const {
    return std::find(handles.begin(), handles.end(), h32(handle)) != handles.end();
}

void AttributeHandles::remove(RTI::AttributeHandle handle) {
    if (!list_.erase(handle))
        throw RTI::AttributeNotDefined(("attribute " + std::to_string(handle) + " is not in the set").c_str());
}

void FederateHandles::remove(RTI::FederateHandle handle) {
    if (!list_.erase(handle))
        throw RTI::ArrayIndexOutOfBounds(("federate " + std::to_string(handle) + " is not in the set").c_str());
}

const wire::HandleValue& Pairs::at(RTI::ULong index) const {
    if (index >= values.size()) out_of_bounds(index, values.size());
    return values[index];
}

void Pairs::add(RTI::Handle handle, const char* value, RTI::ULong length) {
    if (length > 0 && !value) throw RTI::ValueLengthExceeded("a value of non-zero length at a null pointer");
    std::string bytes(value ? value : "", length);
    for (auto& [h, v] : values)
        if (h == h32(handle)) {
            v = std::move(bytes);
            return;
        }
    values.emplace_back(h32(handle), std::move(bytes));
}

void Pairs::remove(RTI::Handle handle) {
    const auto it = std::find_if(values.begin(), values.end(), [&](const auto& p) { return p.first == h32(handle); });
    if (it == values.end()) throw RTI::ArrayIndexOutOfBounds(("handle " + std::to_string(handle) + " is not in the set").c_str());
    values.erase(it);
}

void Pairs::require_received() const {
    if (!received) throw RTI::InvalidHandleValuePairSetContext("only a set given to a callback knows how it came");
}

RTI::TransportType AttributeValues::getTransportType(RTI::ULong index) const {
    pairs_.require_received();
    pairs_.at(index);
    return pairs_.transport;
}
RTI::OrderType AttributeValues::getOrderType(RTI::ULong index) const {
    pairs_.require_received();
    pairs_.at(index);
    return pairs_.order;
}
RTI::Region* AttributeValues::getRegion(RTI::ULong index) const {
    pairs_.require_received();
    pairs_.at(index);
    return nullptr;  // the gateway does not say through which region an update came
}
RTI::TransportType ParameterValues::getTransportType() const {
    pairs_.require_received();
    return pairs_.transport;
}
RTI::OrderType ParameterValues::getOrderType() const {
    pairs_.require_received();
    return pairs_.order;
}
RTI::Region* ParameterValues::getRegion() const {
    pairs_.require_received();
    return nullptr;
}

wire::Handles handles_of(const RTI::AttributeHandleSet& set) {
    if (const auto* ours = dynamic_cast<const AttributeHandles*>(&set)) return ours->handles();
    wire::Handles out;
    for (RTI::ULong i = 0; i < set.size(); ++i) out.push_back(h32(set.getHandle(i)));
    return out;
}

wire::Handles handles_of(const RTI::FederateHandleSet& set) {
    wire::Handles out;
    for (RTI::ULong i = 0; i < set.size(); ++i) out.push_back(h32(set.getHandle(i)));
    return out;
}

namespace {
template <class Set>
wire::HandleValues pairs_of(const Set& set) {
    wire::HandleValues out;
    out.reserve(set.size());
    for (RTI::ULong i = 0; i < set.size(); ++i) {
        RTI::ULong length = 0;
        const char* value = set.getValuePointer(i, length);
        out.emplace_back(h32(set.getHandle(i)), std::string(value, length));
    }
    return out;
}
}  // namespace

wire::HandleValues values_of(const RTI::AttributeHandleValuePairSet& set) {
    if (const auto* ours = dynamic_cast<const AttributeValues*>(&set)) return ours->values();
    return pairs_of(set);
}

wire::HandleValues values_of(const RTI::ParameterHandleValuePairSet& set) {
    if (const auto* ours = dynamic_cast<const ParameterValues*>(&set)) return ours->values();
    return pairs_of(set);
}

// ---- regions ----

FederateRegion::FederateRegion(std::uint32_t handle, fom::Handle space, const Client::Extent& extent)
    : handle_(handle), space_(space), extent_(extent) {}

const Client::Range& FederateRegion::range(RTI::ExtentIndex extent, RTI::DimensionHandle dimension) const {
    if (extent != 0) out_of_bounds(extent, 1);
    for (const auto& r : extent_)
        if (r.dimension == h32(dimension)) return r;
    throw RTI::ArrayIndexOutOfBounds(
        ("dimension " + std::to_string(dimension) + " is not one of the region's routing space").c_str());
}

Client::Range& FederateRegion::range(RTI::ExtentIndex extent, RTI::DimensionHandle dimension) {
    return const_cast<Client::Range&>(static_cast<const FederateRegion*>(this)->range(extent, dimension));
}

RTI::ULong FederateRegion::getRangeLowerBound(RTI::ExtentIndex extent, RTI::DimensionHandle dimension) const {
    return static_cast<RTI::ULong>(range(extent, dimension).lower);
}
RTI::ULong FederateRegion::getRangeUpperBound(RTI::ExtentIndex extent, RTI::DimensionHandle dimension) const {
    return static_cast<RTI::ULong>(range(extent, dimension).upper);
}
// The bound is checked against the axis when the region is notified (InvalidExtents).
void FederateRegion::setRangeLowerBound(RTI::ExtentIndex extent, RTI::DimensionHandle dimension, RTI::ULong bound) {
    range(extent, dimension).lower = static_cast<std::int64_t>(std::min<RTI::ULong>(bound, 0x7FFFFFFFFFFFFFFFUL));
}
void FederateRegion::setRangeUpperBound(RTI::ExtentIndex extent, RTI::DimensionHandle dimension, RTI::ULong bound) {
    range(extent, dimension).upper = static_cast<std::int64_t>(std::min<RTI::ULong>(bound, 0x7FFFFFFFFFFFFFFFUL));
}

}  // namespace hlacore::hla13

// ---- factories ----

RTI::AttributeHandleValuePairSet* RTI::AttributeSetFactory::create(ULong) { return new hlacore::hla13::AttributeValues(); }
RTI::AttributeHandleSet* RTI::AttributeHandleSetFactory::create(ULong) { return new hlacore::hla13::AttributeHandles(); }
RTI::FederateHandleSet* RTI::FederateHandleSetFactory::create(ULong) { return new hlacore::hla13::FederateHandles(); }
RTI::ParameterHandleValuePairSet* RTI::ParameterSetFactory::create(ULong) { return new hlacore::hla13::ParameterValues(); }
