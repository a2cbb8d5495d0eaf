// The inside of libRTI-NG: what an RTIambassador holds (the hlacore client, the federate's ambassador, its
// regions), the set and region types the library makes, and the conversions between the HLA 1.3 types and
// the client's. Not installed.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "RTI.hh"
#include "rti/client/client.hpp"
#include "rti/client/guarded.hpp"

namespace hlacore::hla13 {

// A handle of the HLA 1.3 API as the client's: one beyond 32 bits names nothing (0xFFFFFFFF is never given).
inline std::uint32_t h32(RTI::ULong handle) { return handle > 0xFFFFFFFEUL ? 0xFFFFFFFFu : static_cast<std::uint32_t>(handle); }
inline std::string text(const char* s) { return s ? std::string(s) : std::string(); }
inline RTI::Boolean boolean(bool b) { return b ? RTI::RTI_TRUE : RTI::RTI_FALSE; }
// The time of a FedTime (InvalidFederationTime for a type that is not RTIfedTime).
double time_of(const RTI::FedTime& time);

// Translates the exception being handled (inside a catch block) into the HLA 1.3 exception of the same name:
// hlacore::RtiError by its code (hlacore's own codes become RTIinternalError naming them), bad_alloc into
// MemoryExhausted, any other std::exception into RTIinternalError. An RTI::Exception goes through unchanged.
[[noreturn]] void rethrow_as_hla();

// Runs a service, its failures turned into HLA 1.3 exceptions.
template <class F>
auto guarded(F&& service) -> decltype(service()) {
    return guarded_by(rethrow_as_hla, std::forward<F>(service));
}

// ---- the sets ----

// The handles of a handle set, each once, in the order added.
struct HandleList {
    wire::Handles handles;

    RTI::ULong at(RTI::ULong index) const;  // ArrayIndexOutOfBounds
    void add(RTI::ULong handle);
    bool erase(RTI::ULong handle);  // false when absent
    bool contains(RTI::ULong handle) const;
};

class AttributeHandles final : public RTI::AttributeHandleSet {
public:
    explicit AttributeHandles(wire::Handles handles = {}) : list_{std::move(handles)} {}
    RTI::ULong size() const override { return list_.handles.size(); }
    RTI::AttributeHandle getHandle(RTI::ULong index) const override { return list_.at(index); }
    void add(RTI::AttributeHandle handle) override { list_.add(handle); }
    void remove(RTI::AttributeHandle handle) override;  // AttributeNotDefined when absent
    void empty() override { list_.handles.clear(); }
    RTI::Boolean isEmpty() const override { return boolean(list_.handles.empty()); }
    RTI::Boolean isMember(RTI::AttributeHandle handle) const override { return boolean(list_.contains(handle)); }
    const wire::Handles& handles() const { return list_.handles; }

private:
    HandleList list_;
};

class FederateHandles final : public RTI::FederateHandleSet {
public:
    RTI::ULong size() const override { return list_.handles.size(); }
    RTI::FederateHandle getHandle(RTI::ULong index) const override { return list_.at(index); }
    void add(RTI::FederateHandle handle) override { list_.add(handle); }
    void remove(RTI::FederateHandle handle) override;  // ArrayIndexOutOfBounds when absent
    void empty() override { list_.handles.clear(); }
    RTI::Boolean isMember(RTI::FederateHandle handle) const override { return boolean(list_.contains(handle)); }

private:
    HandleList list_;
};

// The pairs of an attribute or parameter set, with how they came when received (a callback's argument).
struct Pairs {
    wire::HandleValues values;
    bool received = false;
    std::uint8_t order = 1;
    std::uint8_t transport = 1;

    const wire::HandleValue& at(RTI::ULong index) const;  // ArrayIndexOutOfBounds
    void add(RTI::Handle handle, const char* value, RTI::ULong length);
    void remove(RTI::Handle handle);
    void require_received() const;  // InvalidHandleValuePairSetContext
};

// What the attribute and parameter pair sets share (Base is either interface).
template <class Base>
class PairSet : public Base {
public:
    explicit PairSet(Pairs pairs) : pairs_(std::move(pairs)) {}
    using Base::getValue;  // the unsigned int overloads too
    using Base::getValuePointer;
    RTI::ULong size() const override { return pairs_.values.size(); }
    RTI::Handle getHandle(RTI::ULong index) const override { return pairs_.at(index).first; }
    RTI::ULong getValueLength(RTI::ULong index) const override { return pairs_.at(index).second.size(); }
    void getValue(RTI::ULong index, char* buffer, RTI::ULong& length) const override {
        const wire::Value& value = pairs_.at(index).second;
        value.view().copy(buffer, value.size());
        length = value.size();
    }
    char* getValuePointer(RTI::ULong index, RTI::ULong& length) const override {
        const wire::Value& value = pairs_.at(index).second;
        length = value.size();
        return const_cast<char*>(value.data());  // HLA 1.3's signature; the federate reads it
    }
    void add(RTI::Handle handle, const char* value, RTI::ULong length) override { pairs_.add(handle, value, length); }
    void remove(RTI::Handle handle) override { pairs_.remove(handle); }
    void moveFrom(const Base& other, RTI::ULong& index) override {
        RTI::ULong length = 0;
        const char* value = other.getValuePointer(index, length);
        add(other.getHandle(index), value, length);
        ++index;
    }
    void empty() override { pairs_.values.clear(); }
    RTI::ULong start() const override { return 0; }
    RTI::ULong valid(RTI::ULong index) const override { return index < size(); }
    RTI::ULong next(RTI::ULong index) const override { return index + 1; }
    const wire::HandleValues& values() const { return pairs_.values; }

protected:
    Pairs pairs_;
};

class AttributeValues final : public PairSet<RTI::AttributeHandleValuePairSet> {
public:
    explicit AttributeValues(Pairs pairs = {}) : PairSet(std::move(pairs)) {}
    RTI::TransportType getTransportType(RTI::ULong index) const override;
    RTI::OrderType getOrderType(RTI::ULong index) const override;
    RTI::Region* getRegion(RTI::ULong index) const override;
};

class ParameterValues final : public PairSet<RTI::ParameterHandleValuePairSet> {
public:
    explicit ParameterValues(Pairs pairs = {}) : PairSet(std::move(pairs)) {}
    RTI::TransportType getTransportType() const override;
    RTI::OrderType getOrderType() const override;
    RTI::Region* getRegion() const override;
};

// The retraction handle of a timestamped message.
inline RTI::EventRetractionHandle retraction(std::uint32_t sender, std::uint64_t serial) {
    RTI::EventRetractionHandle h;
    h.theSerialNumber = static_cast<RTI::UniqueID>(serial);
    h.sendingFederate = sender;
    return h;
}

// The handles and pairs of any implementation of the sets (this library's are read directly).
wire::Handles handles_of(const RTI::AttributeHandleSet& set);
wire::Handles handles_of(const RTI::FederateHandleSet& set);
wire::HandleValues values_of(const RTI::AttributeHandleValuePairSet& set);
wire::HandleValues values_of(const RTI::ParameterHandleValuePairSet& set);

// A region of this federate: its handle at the gateway, its routing space and one extent, a range per
// dimension of the space. Bounds set here are sent by notifyAboutRegionModification.
class FederateRegion final : public RTI::Region {
public:
    FederateRegion(std::uint32_t handle, fom::Handle space, const Client::Extent& extent);
    RTI::ULong getRangeLowerBound(RTI::ExtentIndex extent, RTI::DimensionHandle dimension) const override;
    RTI::ULong getRangeUpperBound(RTI::ExtentIndex extent, RTI::DimensionHandle dimension) const override;
    void setRangeLowerBound(RTI::ExtentIndex extent, RTI::DimensionHandle dimension, RTI::ULong bound) override;
    void setRangeUpperBound(RTI::ExtentIndex extent, RTI::DimensionHandle dimension, RTI::ULong bound) override;
    RTI::SpaceHandle getSpaceHandle() const noexcept override { return space_; }
    RTI::ULong getNumberOfExtents() const noexcept override { return 1; }
    RTI::ULong getRangeLowerBoundNotificationLimit(RTI::ExtentIndex extent, RTI::DimensionHandle dimension) const override {
        return getRangeLowerBound(extent, dimension);
    }
    RTI::ULong getRangeUpperBoundNotificationLimit(RTI::ExtentIndex extent, RTI::DimensionHandle dimension) const override {
        return getRangeUpperBound(extent, dimension);
    }
    std::uint32_t handle() const { return handle_; }
    const Client::Extent& extent() const { return extent_; }

private:
    Client::Range& range(RTI::ExtentIndex extent, RTI::DimensionHandle dimension);
    const Client::Range& range(RTI::ExtentIndex extent, RTI::DimensionHandle dimension) const;

    std::uint32_t handle_;
    fom::Handle space_;
    Client::Extent extent_;
};

}  // namespace hlacore::hla13

// What an RTIambassador holds.
class RTIambPrivateRefs {
public:
    explicit RTIambPrivateRefs(hlacore::ClientOptions options, const std::string& host, std::uint16_t port)
        : client(host, port, std::move(options)) {}

    hlacore::Client client;
    RTI::FederateAmbassador* federate = nullptr;  // from joinFederationExecution
    // The regions createRegion made and deleteRegion has not deleted, by handle (the region token).
    std::map<std::uint32_t, hlacore::hla13::FederateRegion*> regions;

    // The region as this federate's (RegionNotKnown for one it did not make, or deleted).
    hlacore::hla13::FederateRegion& known(const RTI::Region& region);
    // Delivers one message from the gateway to the federate's ambassador (callbacks.cpp).
    void deliver(hlacore::wire::Message& message);
};
