// What the C++ test federates of HLA 1.3 share: CHECK (../check.hh), a FederateAmbassador that records every
// callback, and ticking until a condition holds (bounded).
#pragma once

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "../check.hh"
#include "NullFederateAmbassador.hh"
#include "RTI.hh"
#include "fedtime.hh"


// One callback: its name and what it carried.
struct Event {
    std::string name;
    RTI::ULong handle = 0;                       // object, or interaction class
    std::vector<RTI::ULong> handles;             // attributes
    std::map<RTI::ULong, std::string> values;    // attribute or parameter values
    double time = NAN;
    std::string text;                            // label, tag or object name
    RTI::ULong other = 0;                        // owner, federate, class
};

// A set of one attribute's value, as the test federates send it.
inline std::unique_ptr<RTI::AttributeHandleValuePairSet> attribute_values(RTI::AttributeHandle h, const std::string& value) {
    std::unique_ptr<RTI::AttributeHandleValuePairSet> set(RTI::AttributeSetFactory::create(1));
    set->add(h, value.data(), static_cast<RTI::ULong>(value.size()));
    return set;
}

inline std::vector<RTI::ULong> handles_in(const RTI::AttributeHandleSet& set) {
    std::vector<RTI::ULong> out;
    for (RTI::ULong i = 0; i < set.size(); ++i) out.push_back(set.getHandle(i));
    return out;
}

template <class Set>
std::map<RTI::ULong, std::string> values_in(const Set& set) {
    std::map<RTI::ULong, std::string> out;
    for (RTI::ULong i = set.start(); set.valid(i); i = set.next(i)) {
        unsigned int length = 0;  // OpenRTI's ULong: the header takes both
        const char* value = set.getValuePointer(i, length);
        out[set.getHandle(i)] = std::string(value, length);
    }
    return out;
}

inline double seconds(const RTI::FedTime& t) { return static_cast<const RTIfedTime&>(t).getTime(); }

class Recorder : public NullFederateAmbassador {
public:
    std::vector<Event> events;

    std::vector<const Event*> saw(const std::string& name) const {
        std::vector<const Event*> out;
        for (const auto& e : events)
            if (e.name == name) out.push_back(&e);
        return out;
    }
    std::size_t count(const std::string& name) const { return saw(name).size(); }
    std::vector<double> grants() const {
        std::vector<double> out;
        for (const auto* e : saw("timeAdvanceGrant")) out.push_back(e->time);
        return out;
    }

    void synchronizationPointRegistrationSucceeded(const char* label) override { add("synchronizationPointRegistrationSucceeded").text = label; }
    void synchronizationPointRegistrationFailed(const char* label) override { add("synchronizationPointRegistrationFailed").text = label; }
    void announceSynchronizationPoint(const char* label, const char*) override { add("announceSynchronizationPoint").text = label; }
    void federationSynchronized(const char* label) override { add("federationSynchronized").text = label; }
    void initiateFederateSave(const char* label) override { add("initiateFederateSave").text = label; }
    void federationSaved() override { add("federationSaved"); }
    void federationNotSaved() override { add("federationNotSaved"); }
    void requestFederationRestoreSucceeded(const char* label) override { add("requestFederationRestoreSucceeded").text = label; }
    void requestFederationRestoreFailed(const char* label, const char*) override { add("requestFederationRestoreFailed").text = label; }
    void federationRestoreBegun() override { add("federationRestoreBegun"); }
    void initiateFederateRestore(const char* label, RTI::FederateHandle federate) override {
        Event& e = add("initiateFederateRestore");
        e.text = label;
        e.other = federate;
    }
    void federationRestored() override { add("federationRestored"); }
    void federationNotRestored() override { add("federationNotRestored"); }
    void startRegistrationForObjectClass(RTI::ObjectClassHandle c) override { add("startRegistrationForObjectClass").handle = c; }
    void stopRegistrationForObjectClass(RTI::ObjectClassHandle c) override { add("stopRegistrationForObjectClass").handle = c; }
    void turnInteractionsOn(RTI::InteractionClassHandle c) override { add("turnInteractionsOn").handle = c; }
    void turnInteractionsOff(RTI::InteractionClassHandle c) override { add("turnInteractionsOff").handle = c; }
    void discoverObjectInstance(RTI::ObjectHandle o, RTI::ObjectClassHandle c, const char* name) override {
        Event& e = add("discoverObjectInstance");
        e.handle = o;
        e.other = c;
        e.text = name;
    }
    void reflectAttributeValues(RTI::ObjectHandle o, const RTI::AttributeHandleValuePairSet& values, const RTI::FedTime& t,
                                const char* tag, RTI::EventRetractionHandle) override {
        reflect(o, values, tag).time = seconds(t);
    }
    void reflectAttributeValues(RTI::ObjectHandle o, const RTI::AttributeHandleValuePairSet& values, const char* tag) override {
        reflect(o, values, tag);
    }
    void receiveInteraction(RTI::InteractionClassHandle c, const RTI::ParameterHandleValuePairSet& values,
                            const RTI::FedTime& t, const char* tag, RTI::EventRetractionHandle) override {
        receive(c, values, tag).time = seconds(t);
    }
    void receiveInteraction(RTI::InteractionClassHandle c, const RTI::ParameterHandleValuePairSet& values, const char* tag) override {
        receive(c, values, tag);
    }
    void removeObjectInstance(RTI::ObjectHandle o, const RTI::FedTime& t, const char* tag, RTI::EventRetractionHandle) override {
        Event& e = add("removeObjectInstance");
        e.handle = o;
        e.time = seconds(t);
        e.text = tag;
    }
    void removeObjectInstance(RTI::ObjectHandle o, const char* tag) override {
        Event& e = add("removeObjectInstance");
        e.handle = o;
        e.text = tag;
    }
    void attributesInScope(RTI::ObjectHandle o, const RTI::AttributeHandleSet& a) override { attributes("attributesInScope", o, a); }
    void attributesOutOfScope(RTI::ObjectHandle o, const RTI::AttributeHandleSet& a) override { attributes("attributesOutOfScope", o, a); }
    void provideAttributeValueUpdate(RTI::ObjectHandle o, const RTI::AttributeHandleSet& a) override { attributes("provideAttributeValueUpdate", o, a); }
    void turnUpdatesOnForObjectInstance(RTI::ObjectHandle o, const RTI::AttributeHandleSet& a) override { attributes("turnUpdatesOnForObjectInstance", o, a); }
    void turnUpdatesOffForObjectInstance(RTI::ObjectHandle o, const RTI::AttributeHandleSet& a) override { attributes("turnUpdatesOffForObjectInstance", o, a); }
    void requestAttributeOwnershipAssumption(RTI::ObjectHandle o, const RTI::AttributeHandleSet& a, const char*) override {
        attributes("requestAttributeOwnershipAssumption", o, a);
    }
    void attributeOwnershipDivestitureNotification(RTI::ObjectHandle o, const RTI::AttributeHandleSet& a) override {
        attributes("attributeOwnershipDivestitureNotification", o, a);
    }
    void attributeOwnershipAcquisitionNotification(RTI::ObjectHandle o, const RTI::AttributeHandleSet& a) override {
        attributes("attributeOwnershipAcquisitionNotification", o, a);
    }
    void attributeOwnershipUnavailable(RTI::ObjectHandle o, const RTI::AttributeHandleSet& a) override {
        attributes("attributeOwnershipUnavailable", o, a);
    }
    void requestAttributeOwnershipRelease(RTI::ObjectHandle o, const RTI::AttributeHandleSet& a, const char*) override {
        attributes("requestAttributeOwnershipRelease", o, a);
    }
    void confirmAttributeOwnershipAcquisitionCancellation(RTI::ObjectHandle o, const RTI::AttributeHandleSet& a) override {
        attributes("confirmAttributeOwnershipAcquisitionCancellation", o, a);
    }
    void informAttributeOwnership(RTI::ObjectHandle o, RTI::AttributeHandle a, RTI::FederateHandle owner) override {
        Event& e = add("informAttributeOwnership");
        e.handle = o;
        e.handles = {a};
        e.other = owner;
    }
    void attributeIsNotOwned(RTI::ObjectHandle o, RTI::AttributeHandle a) override {
        Event& e = add("attributeIsNotOwned");
        e.handle = o;
        e.handles = {a};
    }
    void attributeOwnedByRTI(RTI::ObjectHandle o, RTI::AttributeHandle a) override {
        Event& e = add("attributeOwnedByRTI");
        e.handle = o;
        e.handles = {a};
    }
    void timeRegulationEnabled(const RTI::FedTime& t) override { add("timeRegulationEnabled").time = seconds(t); }
    void timeConstrainedEnabled(const RTI::FedTime& t) override { add("timeConstrainedEnabled").time = seconds(t); }
    void timeAdvanceGrant(const RTI::FedTime& t) override { add("timeAdvanceGrant").time = seconds(t); }
    void requestRetraction(RTI::EventRetractionHandle h) override { add("requestRetraction").handle = h.theSerialNumber; }

private:
    Event& add(const char* name) {
        events.push_back(Event{});
        events.back().name = name;
        return events.back();
    }
    // A reflection (an object's attribute values) or an interaction (a class's parameter values).
    template <class Values>
    Event& valued(const char* name, RTI::Handle h, const Values& values, const char* tag) {
        Event& e = add(name);
        e.handle = h;
        e.values = values_in(values);
        e.text = tag;
        return e;
    }
    Event& reflect(RTI::ObjectHandle o, const RTI::AttributeHandleValuePairSet& values, const char* tag) {
        return valued("reflectAttributeValues", o, values, tag);
    }
    Event& receive(RTI::InteractionClassHandle c, const RTI::ParameterHandleValuePairSet& values, const char* tag) {
        return valued("receiveInteraction", c, values, tag);
    }
    void attributes(const char* name, RTI::ObjectHandle o, const RTI::AttributeHandleSet& a) {
        Event& e = add(name);
        e.handle = o;
        e.handles = handles_in(a);
    }
};

// Ticks every ambassador until predicate() holds; exits with a message after `timeout_s`.
inline void tick_until(const std::function<bool()>& predicate, std::initializer_list<RTI::RTIambassador*> ambassadors,
                       const char* what, double timeout_s = 10.0) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (!predicate()) {
        if (std::chrono::steady_clock::now() > deadline) {
            std::fprintf(stderr, "not reached within %.0f s: %s\n", timeout_s, what);
            std::exit(1);
        }
        for (auto* a : ambassadors) a->tick(0.01, 0.05);
    }
}

// Returns once the gateway has handled what this federate sent before (it asks to destroy a federation
// that does not exist), as hlacore.processes.round_trip.
inline void round_trip(RTI::RTIambassador& rtia) {
    try {
        rtia.destroyFederationExecution("hlacore-round-trip");
    } catch (RTI::FederationExecutionDoesNotExist&) {
    }
}

// An attribute set of the given handles, held as OpenRTI's examples hold it (RTI_UNIQUE_PTR).
inline RTI_UNIQUE_PTR<RTI::AttributeHandleSet> attribute_set(std::initializer_list<RTI::AttributeHandle> handles) {
    RTI_UNIQUE_PTR<RTI::AttributeHandleSet> set(RTI::AttributeHandleSetFactory::create(handles.size()));
    for (auto h : handles) set->add(h);
    return set;
}

// A test federate joined to `federation` as `name`, recording its callbacks, ticked until a condition holds.
struct TestFederate {
    RTI::RTIambassador rtia;
    Recorder amb;
    TestFederate(const std::string& name, const char* federation) {
        rtia.joinFederationExecution(name.c_str(), federation, &amb);
    }
    void until(const std::function<bool()>& done, const char* what) { tick_until(done, {&rtia}, what, 60.0); }
};

// The last line of a lockstep program: its steps, the timestamped reflections, the grants that came too early.
inline void print_lockstep_summary(int steps, int reflections, int late) {
    std::printf("{\"steps\": %d, \"reflections\": %d, \"late\": %d}\n", steps, reflections, late);
    std::fflush(stdout);
}
