// Every HLA 1.3 service of RTI::RTIambassador called once from C++, through a gateway ($HLACORE_RTIG):
// the scenario of tests/rti/test_hla13_services.py, written against RTI.hh. Exits 0 and prints the number of
// services called when all behaved; tests/system/test_cpp_api.py runs it.
#include <cstring>
#include <iostream>
#include <memory>
#include <set>
#include <string>

#include "recorder.hh"

namespace {

std::set<std::string> called;

// Calls a service of a federate's ambassador, noting its name.
#define CALL(fed, service, ...) (called.insert(#service), (fed).rtia.service(__VA_ARGS__))

struct Session {
    RTI::RTIambassador rtia;
    Recorder amb;
};

const char* const kServices[] = {
    // federation management
    "createFederationExecution", "destroyFederationExecution", "joinFederationExecution", "resignFederationExecution",
    "registerFederationSynchronizationPoint", "synchronizationPointAchieved", "requestFederationSave",
    "federateSaveBegun", "federateSaveComplete", "federateSaveNotComplete", "requestFederationRestore",
    "federateRestoreComplete", "federateRestoreNotComplete",
    // declaration management
    "publishObjectClass", "unpublishObjectClass", "publishInteractionClass", "unpublishInteractionClass",
    "subscribeObjectClassAttributes", "unsubscribeObjectClass", "subscribeInteractionClass", "unsubscribeInteractionClass",
    // object management
    "registerObjectInstance", "updateAttributeValues", "sendInteraction", "deleteObjectInstance",
    "localDeleteObjectInstance", "changeAttributeTransportationType", "changeInteractionTransportationType",
    "requestObjectAttributeValueUpdate", "requestClassAttributeValueUpdate",
    // ownership management
    "unconditionalAttributeOwnershipDivestiture", "negotiatedAttributeOwnershipDivestiture",
    "attributeOwnershipAcquisition", "attributeOwnershipAcquisitionIfAvailable", "attributeOwnershipReleaseResponse",
    "cancelNegotiatedAttributeOwnershipDivestiture", "cancelAttributeOwnershipAcquisition", "queryAttributeOwnership",
    "isAttributeOwnedByFederate",
    // time management
    "enableTimeRegulation", "disableTimeRegulation", "enableTimeConstrained", "disableTimeConstrained",
    "timeAdvanceRequest", "timeAdvanceRequestAvailable", "nextEventRequest", "nextEventRequestAvailable",
    "flushQueueRequest", "enableAsynchronousDelivery", "disableAsynchronousDelivery", "queryLBTS", "queryFederateTime",
    "queryMinNextEventTime", "modifyLookahead", "queryLookahead", "retract", "changeAttributeOrderType",
    "changeInteractionOrderType",
    // data distribution management
    "createRegion", "notifyAboutRegionModification", "deleteRegion", "registerObjectInstanceWithRegion",
    "associateRegionForUpdates", "unassociateRegionForUpdates", "subscribeObjectClassAttributesWithRegion",
    "unsubscribeObjectClassWithRegion", "subscribeInteractionClassWithRegion", "unsubscribeInteractionClassWithRegion",
    "sendInteractionWithRegion", "requestClassAttributeValueUpdateWithRegion",
    // support services
    "getObjectClassHandle", "getObjectClassName", "getAttributeHandle", "getAttributeName", "getInteractionClassHandle",
    "getInteractionClassName", "getParameterHandle", "getParameterName", "getObjectInstanceHandle",
    "getObjectInstanceName", "getRoutingSpaceHandle", "getRoutingSpaceName", "getDimensionHandle", "getDimensionName",
    "getAttributeRoutingSpaceHandle", "getObjectClass", "getInteractionRoutingSpaceHandle", "getTransportationHandle",
    "getTransportationName", "getOrderingHandle", "getOrderingName", "enableClassRelevanceAdvisorySwitch",
    "disableClassRelevanceAdvisorySwitch", "enableAttributeRelevanceAdvisorySwitch",
    "disableAttributeRelevanceAdvisorySwitch", "enableAttributeScopeAdvisorySwitch", "disableAttributeScopeAdvisorySwitch",
    "enableInteractionRelevanceAdvisorySwitch", "disableInteractionRelevanceAdvisorySwitch", "tick",
    "getRegionToken", "getRegion",
};

// A name a support service returned (new[]'d), compared and freed.
bool named(char* name, const char* expected) {
    const bool same = std::strcmp(name, expected) == 0;
    delete[] name;
    return same;
}

std::unique_ptr<RTI::ParameterHandleValuePairSet> parameters(RTI::ParameterHandle h, const char* value) {
    std::unique_ptr<RTI::ParameterHandleValuePairSet> set(RTI::ParameterSetFactory::create(1));
    set->add(h, value, std::strlen(value));
    return set;
}

bool has_parameter(const Recorder& r, RTI::ParameterHandle h, const std::string& value) {
    for (const auto* e : r.saw("receiveInteraction"))
        if (e->values.count(h) && e->values.at(h) == value) return true;
    return false;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: services DDM_FED_FILE\n";
        return 2;
    }
    try {
        RTI::RTIambassador creator;
        called.insert("createFederationExecution");
        creator.createFederationExecution("CppServices", argv[1]);
        Session a, b;
        CALL(a, joinFederationExecution, "a", "CppServices", &a.amb);
        const RTI::FederateHandle b_handle = CALL(b, joinFederationExecution, "b", "CppServices", &b.amb);
        const auto until = [&](const std::function<bool()>& p, const char* what) { tick_until(p, {&a.rtia, &b.rtia}, what); };

        // Support services (§10).
        const auto vehicle = CALL(a, getObjectClassHandle, "vehicle");
        CHECK(named(CALL(a, getObjectClassName, vehicle), "vehicle"));
        const auto position = CALL(a, getAttributeHandle, "position", vehicle);
        const auto speed = a.rtia.getAttributeHandle("speed", vehicle);
        CHECK(named(CALL(a, getAttributeName, position, vehicle), "position"));
        const auto radio = CALL(a, getInteractionClassHandle, "radio");
        CHECK(named(CALL(a, getInteractionClassName, radio), "radio"));
        const auto text = CALL(a, getParameterHandle, "text", radio);
        CHECK(named(CALL(a, getParameterName, text, radio), "text"));
        const auto reliable = CALL(a, getTransportationHandle, "HLAreliable");
        const auto best_effort = a.rtia.getTransportationHandle("HLAbestEffort");
        CHECK(named(CALL(a, getTransportationName, best_effort), "HLAbestEffort"));
        const auto timestamp = CALL(a, getOrderingHandle, "Timestamp");
        const auto receive = a.rtia.getOrderingHandle("Receive");
        CHECK(named(CALL(a, getOrderingName, receive), "Receive"));
        const auto geo = CALL(a, getRoutingSpaceHandle, "Geo");
        CHECK(named(CALL(a, getRoutingSpaceName, geo), "Geo"));
        const auto x = CALL(a, getDimensionHandle, "X", geo);
        CHECK(named(CALL(a, getDimensionName, x, geo), "X"));
        CHECK(CALL(a, getAttributeRoutingSpaceHandle, position, vehicle) == geo);
        CHECK(CALL(a, getInteractionRoutingSpaceHandle, radio) == geo);
        CALL(a, enableClassRelevanceAdvisorySwitch);
        CALL(a, disableClassRelevanceAdvisorySwitch);
        CALL(a, enableAttributeRelevanceAdvisorySwitch);
        CALL(a, disableAttributeRelevanceAdvisorySwitch);
        CALL(a, enableAttributeScopeAdvisorySwitch);
        CALL(a, disableAttributeScopeAdvisorySwitch);
        CALL(a, enableInteractionRelevanceAdvisorySwitch);
        CALL(a, disableInteractionRelevanceAdvisorySwitch);
        a.rtia.enableClassRelevanceAdvisorySwitch();
        CALL(a, tick);
        try {
            a.rtia.getObjectClassHandle("no such class");
            CHECK(!"getObjectClassHandle of an unknown name raised");
        } catch (RTI::NameNotFound&) {
        }

        // Declaration management (§5) and synchronization points (§4.6-4.10).
        const auto both = attribute_set({position, speed});
        CALL(a, publishObjectClass, vehicle, *both);
        b.rtia.publishObjectClass(vehicle, *both);
        CALL(b, subscribeObjectClassAttributes, vehicle, *both, RTI::RTI_TRUE);
        CALL(a, publishInteractionClass, radio);
        CALL(b, subscribeInteractionClass, radio, RTI::RTI_TRUE);
        round_trip(b.rtia);
        CALL(a, registerFederationSynchronizationPoint, "ready", "");
        until([&] { return a.amb.count("announceSynchronizationPoint") && b.amb.count("announceSynchronizationPoint"); },
              "ready announced");
        CALL(a, synchronizationPointAchieved, "ready");
        b.rtia.synchronizationPointAchieved("ready");
        until([&] { return a.amb.count("federationSynchronized") && b.amb.count("federationSynchronized"); },
              "ready synchronized");
        {   // a synchronization point for a set of federates
            std::unique_ptr<RTI::FederateHandleSet> only_b(RTI::FederateHandleSetFactory::create(1));
            only_b->add(b_handle);
            a.rtia.registerFederationSynchronizationPoint("b-only", "", *only_b);
            until([&] { return b.amb.count("announceSynchronizationPoint") == 2; }, "b-only announced to b");
            b.rtia.synchronizationPointAchieved("b-only");
            until([&] { return b.amb.count("federationSynchronized") == 2; }, "b-only synchronized");
            CHECK(a.amb.count("announceSynchronizationPoint") == 1 && a.amb.count("federationSynchronized") == 1);
        }

        // Object management (§6).
        const auto obj = CALL(a, registerObjectInstance, vehicle, "r1");
        until([&] { return b.amb.count("discoverObjectInstance") == 1; }, "r1 discovered");
        CHECK(b.amb.saw("discoverObjectInstance")[0]->text == "r1");
        CHECK(CALL(a, getObjectInstanceHandle, "r1") == obj);
        CHECK(named(CALL(a, getObjectInstanceName, obj), "r1"));
        CHECK(CALL(a, getObjectClass, obj) == vehicle);
        CALL(a, updateAttributeValues, obj, *attribute_values(position, "here"), "");
        CALL(a, sendInteraction, radio, *parameters(text, "go"), "");
        until([&] { return b.amb.count("reflectAttributeValues") && b.amb.count("receiveInteraction"); }, "update and interaction");
        CHECK(b.amb.saw("reflectAttributeValues")[0]->values.at(position) == "here");
        CHECK(has_parameter(b.amb, text, "go"));
        CALL(b, requestObjectAttributeValueUpdate, obj, *attribute_set({position}));
        CALL(b, requestClassAttributeValueUpdate, vehicle, *attribute_set({speed}));
        until([&] { return a.amb.count("provideAttributeValueUpdate") == 2; }, "two provideAttributeValueUpdate");
        CALL(a, changeAttributeTransportationType, obj, *attribute_set({position}), best_effort);
        CALL(a, changeInteractionTransportationType, radio, reliable);
        CALL(a, changeAttributeOrderType, obj, *attribute_set({position}), receive);
        CALL(a, changeInteractionOrderType, radio, timestamp);

        // Ownership management (§7): speed goes to b by negotiation and comes back unconditionally; a asks
        // for position back and cancels, b releases it on request.
        const auto speed_only = attribute_set({speed});
        const auto position_only = attribute_set({position});
        CALL(a, negotiatedAttributeOwnershipDivestiture, obj, *speed_only, "");
        CALL(a, cancelNegotiatedAttributeOwnershipDivestiture, obj, *speed_only);
        a.rtia.negotiatedAttributeOwnershipDivestiture(obj, *speed_only, "");
        until([&] { return b.amb.count("requestAttributeOwnershipAssumption") >= 1; }, "assumption asked");
        CALL(b, attributeOwnershipAcquisition, obj, *speed_only, "");
        until([&] { return b.amb.count("attributeOwnershipAcquisitionNotification") >= 1; }, "b acquires speed");
        CALL(b, unconditionalAttributeOwnershipDivestiture, obj, *speed_only);
        CALL(a, attributeOwnershipAcquisitionIfAvailable, obj, *speed_only);
        until([&] { return a.amb.count("attributeOwnershipAcquisitionNotification") == 1; }, "a takes speed back");
        b.rtia.attributeOwnershipAcquisition(obj, *position_only, "");
        until([&] { return a.amb.count("requestAttributeOwnershipRelease") >= 1; }, "release asked of a");
        {
            std::unique_ptr<RTI::AttributeHandleSet> released(CALL(a, attributeOwnershipReleaseResponse, obj, *position_only));
            CHECK(released->size() == 1 && released->getHandle(0) == position);
        }
        until([&] { return b.amb.count("attributeOwnershipAcquisitionNotification") == 2; }, "b acquires position");
        a.rtia.attributeOwnershipAcquisition(obj, *position_only, "");
        until([&] { return b.amb.count("requestAttributeOwnershipRelease") >= 1; }, "release asked of b");
        CALL(a, cancelAttributeOwnershipAcquisition, obj, *position_only);
        until([&] { return a.amb.count("confirmAttributeOwnershipAcquisitionCancellation") >= 1; }, "cancellation confirmed");
        CALL(a, queryAttributeOwnership, obj, position);
        until([&] { return a.amb.count("informAttributeOwnership") >= 1; }, "ownership informed");
        CHECK(a.amb.saw("informAttributeOwnership")[0]->other == b_handle);
        CHECK(CALL(a, isAttributeOwnedByFederate, obj, speed) == RTI::RTI_TRUE);
        CHECK(a.rtia.isAttributeOwnedByFederate(obj, position) == RTI::RTI_FALSE);

        // Time management (§8): both regulating and constrained, each kind of advance once.
        for (Session* fed : {&a, &b}) {
            CALL(*fed, enableTimeRegulation, RTIfedTime(0.0), RTIfedTime(1.0));
            CALL(*fed, enableTimeConstrained);
        }
        until([&] {
            for (Session* f : {&a, &b})
                if (f->amb.count("timeRegulationEnabled") != 1 || f->amb.count("timeConstrainedEnabled") != 1) return false;
            return true;
        }, "regulating and constrained");
        CALL(a, modifyLookahead, RTIfedTime(2.0));
        RTIfedTime t;
        CALL(a, queryLookahead, t);
        CHECK(t == 2.0);
        CALL(a, queryFederateTime, t);
        CHECK(t == 0.0);
        CALL(a, queryLBTS, t);
        CHECK(t == 1.0);
        CALL(a, queryMinNextEventTime, t);
        CALL(a, enableAsynchronousDelivery);
        CALL(a, disableAsynchronousDelivery);
        CALL(a, retract, CALL(a, sendInteraction, radio, *parameters(text, "never"), RTIfedTime(5.0), ""));
        CALL(a, timeAdvanceRequest, RTIfedTime(10.0));
        CALL(b, timeAdvanceRequestAvailable, RTIfedTime(10.0));
        until([&] { return a.amb.grants() == std::vector<double>{10} && b.amb.grants() == std::vector<double>{10}; }, "grants at 10");
        CALL(a, nextEventRequest, RTIfedTime(20.0));
        CALL(b, nextEventRequestAvailable, RTIfedTime(20.0));
        until([&] { return a.amb.grants() == std::vector<double>{10, 20} && b.amb.grants() == std::vector<double>{10, 20}; },
              "grants at 20");
        CALL(a, flushQueueRequest, RTIfedTime(30.0));  // granted at once, at its LBTS: b's 20 + lookahead 1
        until([&] { return a.amb.grants() == std::vector<double>{10, 20, 21}; }, "flush granted at 21");
        CHECK(!has_parameter(b.amb, text, "never"));
        for (Session* fed : {&a, &b}) {
            CALL(*fed, disableTimeRegulation);
            CALL(*fed, disableTimeConstrained);
        }

        // Data distribution management (§9): b listens in X [0, 10]; a's vehicle r3 is at X 5.
        RTI::Region* near = CALL(b, createRegion, geo, 1);
        near->setRangeLowerBound(0, x, 0);
        near->setRangeUpperBound(0, x, 10);
        CALL(b, notifyAboutRegionModification, *near);
        CHECK(near->getRangeUpperBound(0, x) == 10 && near->getNumberOfExtents() == 1);
        CHECK(CALL(b, getRegion, CALL(b, getRegionToken, near)) == near);
        CALL(b, subscribeObjectClassAttributesWithRegion, vehicle, *near, *position_only, RTI::RTI_TRUE);
        CALL(b, subscribeInteractionClassWithRegion, radio, *near, RTI::RTI_TRUE);
        RTI::Region* here = a.rtia.createRegion(geo, 1);
        here->setRangeLowerBound(0, x, 5);
        here->setRangeUpperBound(0, x, 5);
        a.rtia.notifyAboutRegionModification(*here);
        RTI::AttributeHandle tracked_attributes[] = {position};
        RTI::Region* tracked_regions[] = {here};
        const auto tracked = CALL(a, registerObjectInstanceWithRegion, vehicle, "r3", tracked_attributes, tracked_regions, 1);
        CALL(a, associateRegionForUpdates, *here, tracked, *speed_only);
        round_trip(b.rtia);
        CALL(a, sendInteractionWithRegion, radio, *parameters(text, "near"), "", *here);
        until([&] { return has_parameter(b.amb, text, "near"); }, "interaction through the region");
        CALL(b, requestClassAttributeValueUpdateWithRegion, vehicle, *position_only, *near);
        until([&] {
            for (const auto* e : a.amb.saw("provideAttributeValueUpdate"))
                if (e->handle == tracked && e->handles == std::vector<RTI::ULong>{position}) return true;
            return false;
        }, "provide through the region");
        CALL(a, unassociateRegionForUpdates, *here, tracked);
        CALL(b, unsubscribeObjectClassWithRegion, vehicle, *near);
        CALL(b, unsubscribeInteractionClassWithRegion, radio, *near);
        CALL(a, deleteRegion, here);
        b.rtia.deleteRegion(near);
        try {
            a.rtia.createRegion(geo, 2);
            CHECK(!"createRegion with two extents raised");
        } catch (RTI::InvalidExtents&) {
        }

        // Save and restore (§4.11-4.22): a save, a save one federate fails, a restore one federate fails, a
        // restore.
        CALL(a, requestFederationSave, "snapshot");
        until([&] { return a.amb.count("initiateFederateSave") == 1 && b.amb.count("initiateFederateSave") == 1; }, "save initiated");
        for (Session* fed : {&a, &b}) {
            CALL(*fed, federateSaveBegun);
            CALL(*fed, federateSaveComplete);
        }
        until([&] { return a.amb.count("federationSaved") && b.amb.count("federationSaved"); }, "saved");
        a.rtia.requestFederationSave("broken");
        until([&] { return a.amb.count("initiateFederateSave") == 2 && b.amb.count("initiateFederateSave") == 2; }, "second save");
        a.rtia.federateSaveComplete();
        CALL(b, federateSaveNotComplete);
        until([&] { return a.amb.count("federationNotSaved") && b.amb.count("federationNotSaved"); }, "not saved");
        CALL(a, requestFederationRestore, "snapshot");
        until([&] { return a.amb.count("initiateFederateRestore") == 1 && b.amb.count("initiateFederateRestore") == 1; }, "restore 1");
        CALL(a, federateRestoreComplete);
        CALL(b, federateRestoreNotComplete);
        until([&] { return a.amb.count("federationNotRestored") && b.amb.count("federationNotRestored"); }, "not restored");
        a.rtia.requestFederationRestore("snapshot");
        until([&] { return a.amb.count("initiateFederateRestore") == 2 && b.amb.count("initiateFederateRestore") == 2; }, "restore 2");
        a.rtia.federateRestoreComplete();
        b.rtia.federateRestoreComplete();
        until([&] { return a.amb.count("federationRestored") && b.amb.count("federationRestored"); }, "restored");
        CHECK(a.amb.count("requestFederationRestoreSucceeded") == 2);

        // The end of object and declaration management.
        const auto other = a.rtia.registerObjectInstance(vehicle);  // named by the RTI
        until([&] { return b.amb.count("discoverObjectInstance") == 3; }, "the unnamed object discovered");
        CALL(b, localDeleteObjectInstance, other);
        CALL(a, deleteObjectInstance, obj, "");
        until([&] { return b.amb.count("removeObjectInstance") == 1; }, "r1 removed");
        CALL(b, unsubscribeObjectClass, vehicle);
        CALL(b, unsubscribeInteractionClass, radio);
        CALL(a, unpublishObjectClass, vehicle);
        CALL(a, unpublishInteractionClass, radio);

        for (Session* fed : {&a, &b}) CALL(*fed, resignFederationExecution, RTI::DELETE_OBJECTS_AND_RELEASE_ATTRIBUTES);
        try {
            a.rtia.resignFederationExecution(RTI::DELETE_OBJECTS);
            CHECK(!"a second resign raised");
        } catch (RTI::FederateNotExecutionMember& e) {
            CHECK(e._reason && std::strlen(e._reason) > 0);
        }
        called.insert("destroyFederationExecution");
        creator.destroyFederationExecution("CppServices");
        try {
            creator.destroyFederationExecution("CppServices");
            CHECK(!"destroying it again raised");
        } catch (RTI::FederationExecutionDoesNotExist&) {
        }
    } catch (RTI::Exception& e) {
        std::cerr << "unexpected " << e << "\n";
        return 1;
    }
    int missing = 0;
    for (const char* service : kServices)
        if (!called.count(service)) {
            std::cerr << "not called: " << service << "\n";
            ++missing;
        }
    if (missing) return 1;
    std::cout << "called " << called.size() << " services\n";
    return 0;
}
