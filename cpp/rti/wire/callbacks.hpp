// The federate ambassador's callbacks, by their HLA 1.3 (PyHLA) names, declared once: the binding turns
// each message from the gateway into one of them (cpp/bindings/callbacks.cpp), Python reads the list as
// hlacore._core.CALLBACKS, and tests/rti/test_callbacks.py checks rti.FederateAmbassador's documentation
// against it.
#pragma once

#include <cstddef>

namespace hlacore::wire {

#define HLACORE_CALLBACKS(X)                                                                             \
    /* federation management: synchronization points, save/restore (HLA 1.3 §4) */                        \
    X(synchronizationPointRegistrationSucceeded) X(synchronizationPointRegistrationFailed)               \
    X(announceSynchronizationPoint) X(federationSynchronized)                                            \
    X(initiateFederateSave) X(federationSaved) X(federationNotSaved)                                     \
    X(requestFederationRestoreSucceeded) X(requestFederationRestoreFailed) X(federationRestoreBegun)      \
    X(initiateFederateRestore) X(federationRestored) X(federationNotRestored)                            \
    /* declaration management (§5) */                                                                   \
    X(startRegistrationForObjectClass) X(stopRegistrationForObjectClass)                                 \
    X(turnInteractionsOn) X(turnInteractionsOff)                                                         \
    /* object management (§6) */                                                                         \
    X(discoverObjectInstance) X(reflectAttributeValues) X(receiveInteraction) X(removeObjectInstance)    \
    X(attributesInScope) X(attributesOutOfScope) X(provideAttributeValueUpdate)                          \
    X(turnUpdatesOnForObjectInstance) X(turnUpdatesOffForObjectInstance)                                 \
    /* ownership management (§7) */                                                                      \
    X(requestAttributeOwnershipAssumption) X(attributeOwnershipDivestitureNotification)                  \
    X(attributeOwnershipAcquisitionNotification) X(attributeOwnershipUnavailable)                        \
    X(requestAttributeOwnershipRelease) X(confirmAttributeOwnershipAcquisitionCancellation)              \
    X(informAttributeOwnership) X(attributeIsNotOwned) X(attributeOwnedByRTI)                            \
    /* time management (§8) */                                                                           \
    X(timeRegulationEnabled) X(timeConstrainedEnabled) X(timeAdvanceGrant) X(requestRetraction)

enum class Callback : std::size_t {
#define HLACORE_X(name) name,
    HLACORE_CALLBACKS(HLACORE_X)
#undef HLACORE_X
        Count
};

constexpr const char* kCallbackNames[] = {
#define HLACORE_X(name) #name,
    HLACORE_CALLBACKS(HLACORE_X)
#undef HLACORE_X
};

constexpr const char* callback_name(Callback c) { return kCallbackNames[static_cast<std::size_t>(c)]; }

}  // namespace hlacore::wire
