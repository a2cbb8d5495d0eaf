// The federate ambassador's callbacks, declared once: their HLA 1.3 (PyHLA) names (Python reads the list as
// hlacore._core.CALLBACKS, and tests/rti/test_callbacks.py checks rti.FederateAmbassador's documentation against
// it), the messages that carry them, and the one dispatch of every front end onto its overload per message
// (cpp/bindings/callbacks.cpp, cpp/hla13/callbacks.cpp).
#pragma once

#include <cstddef>
#include <type_traits>
#include <variant>

#include "rti/wire/messages.hpp"

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

// The callbacks only IEEE 1516-2010 has, which no HLA 1.3 federate asks for: the object instance names
// (§6.3, §6.6) and the transportation reports, delivered to hlacore.rti1516e's adapter by the binding.
#define HLACORE_CALLBACKS_1516(X)                                                                        \
    X(objectInstanceNameReservationSucceeded) X(objectInstanceNameReservationFailed)                     \
    X(multipleObjectInstanceNameReservationSucceeded) X(multipleObjectInstanceNameReservationFailed)     \
    X(reportAttributeTransportationType) X(reportInteractionTransportationType)

enum class Callback : std::size_t {
#define HLACORE_X(name) name,
    HLACORE_CALLBACKS(HLACORE_X) HLACORE_CALLBACKS_1516(HLACORE_X)
#undef HLACORE_X
        Count
};

constexpr const char* kCallbackNames[] = {
#define HLACORE_X(name) #name,
    HLACORE_CALLBACKS(HLACORE_X) HLACORE_CALLBACKS_1516(HLACORE_X)
#undef HLACORE_X
};
// The HLA 1.3 callbacks come first: this many.
constexpr std::size_t kHla13Callbacks = static_cast<std::size_t>(Callback::objectInstanceNameReservationSucceeded);

constexpr const char* callback_name(Callback c) { return kCallbackNames[static_cast<std::size_t>(c)]; }

// The messages from the gateway that a federate's ambassador gets as callbacks (one each, or one of a few by a
// flag or a kind: FederationSaved is federationSaved or federationNotSaved), in HLA's order of the groups.
#define HLACORE_CALLBACK_MESSAGES(X)                                                                    \
    X(SyncPointRegistrationSucceeded) X(SyncPointRegistrationFailed) X(AnnounceSyncPoint)              \
    X(FederationSynchronized) X(InitiateFederateSave) X(FederationSaved) X(RestoreRequestAnswer)       \
    X(FederationRestoreBegun) X(InitiateFederateRestore) X(FederationRestored)                         \
    X(StartRegistration) X(StopRegistration) X(TurnInteractionsOn) X(TurnInteractionsOff)              \
    X(DiscoverObject) X(ReflectAttributes) X(ReceiveInteraction) X(RemoveObject) X(AttributesInScope)  \
    X(AttributesOutOfScope) X(ProvideAttributeValueUpdate) X(TurnUpdatesOn) X(TurnUpdatesOff)          \
    X(ObjectNamesReserved) X(AttributeTransportationReported) X(InteractionTransportationReported)     \
    X(RequestOwnershipAssumption) X(DivestitureNotification) X(AcquisitionNotification)                \
    X(OwnershipUnavailable) X(RequestOwnershipRelease) X(ConfirmAcquisitionCancellation)               \
    X(OwnershipInformation)                                                                            \
    X(TimeRegulationEnabled) X(TimeConstrainedEnabled) X(TimeAdvanceGrant) X(RequestRetraction)

// Of those, the callbacks that name a set of an object's attributes and nothing else (ownership, scope,
// updates on or off): message, callback. The front ends make their overloads for these from the list.
#define HLACORE_OBJECT_ATTRIBUTE_CALLBACKS(X) \
    X(ProvideAttributeValueUpdate, provideAttributeValueUpdate)                                          \
    X(DivestitureNotification, attributeOwnershipDivestitureNotification)                                \
    X(AcquisitionNotification, attributeOwnershipAcquisitionNotification)                                \
    X(OwnershipUnavailable, attributeOwnershipUnavailable)                                               \
    X(ConfirmAcquisitionCancellation, confirmAttributeOwnershipAcquisitionCancellation)                  \
    X(AttributesInScope, attributesInScope) X(AttributesOutOfScope, attributesOutOfScope)                \
    X(TurnUpdatesOn, turnUpdatesOnForObjectInstance)                                                     \
    X(TurnUpdatesOff, turnUpdatesOffForObjectInstance)

// HLA 4's callbacks, for the front ends that serve HLA 4's services (the Federate Protocol's, through
// rti1516e::Ambassador's extensions); the others never ask for them and need no overload.
#define HLACORE_HLA4_CALLBACK_MESSAGES(X) X(ReceiveDirectedInteraction)

template <class M>
struct IsCallback : std::false_type {};
template <class M>
struct IsHla4Callback : std::false_type {};
#define HLACORE_X(name) \
    template <>         \
    struct IsCallback<name> : std::true_type {};
HLACORE_CALLBACK_MESSAGES(HLACORE_X)
#undef HLACORE_X
#define HLACORE_X(name) \
    template <>         \
    struct IsHla4Callback<name> : std::true_type {};
HLACORE_HLA4_CALLBACK_MESSAGES(HLACORE_X)
#undef HLACORE_X

// Hands a callback message to a front end (the Python binding, the HLA 1.3 C++ API, the ones to come):
// `front_end(m)` with one overload per message of HLACORE_CALLBACK_MESSAGES, each returning R. A front end
// that misses one does not compile. Any other message (none reaches the callback queue), and an HLA 4 callback
// it has no overload for, goes to front_end.unexpected().
template <class R, class FrontEnd, class Queued>
R dispatch_callback(Queued& message, FrontEnd& front_end) {
    return std::visit(
        [&front_end](auto& m) -> R {
            using M = std::decay_t<decltype(m)>;
            if constexpr (IsCallback<M>::value) {
                static_assert(std::is_invocable_r_v<R, FrontEnd&, decltype(m)>,
                              "a front end has no overload for a message of HLACORE_CALLBACK_MESSAGES");
                return front_end(m);
            } else if constexpr (IsHla4Callback<M>::value && std::is_invocable_r_v<R, FrontEnd&, decltype(m)>) {
                return front_end(m);
            } else {
                return front_end.unexpected();
            }
        },
        message);
}

}  // namespace hlacore::wire
