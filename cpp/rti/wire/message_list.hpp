// The wire protocol's message list: each message's wire code (its place in HLACORE_MESSAGES), the lists
// that declare who serves each (the gateway, a federation's group, the client's checks) and how a message
// declares its fields. The messages themselves are in messages.hpp, their encoding in codec.hpp.
#pragma once

#include <cstdint>

#include "rti/list_codes.hpp"

namespace hlacore::wire {

constexpr std::uint32_t kMagic = 0x484c4143;  // "HLAC"
// 2: initiateFederateRestore's nested records; 3: its SavedTime; 4: Welcome's frame limit, Ping and Pong;
// 5: Welcome's challenge, Authenticate and Authenticated; 6: ClockProbe and ClockEcho; 7: Welcome's datagram
// token and size limit, DatagramHello and DatagramPath; 8: Welcome's nonce, the federation proofs of
// CreateFederation, DestroyFederation and JoinFederation; 9: a typed answer per request with a result
// (FederationJoined ... TimeQueried), Reply only for the others and for refusals; 10: StartRecording,
// RecordedTopic and Recorded; 11: QueryStatus's events_after and instances; 12: CreateFederation's
// time_semantics; 13: CreateFederation's and FederationJoined's time_type, the object instance names'
// ReserveObjectNames, ReleaseObjectNames and ObjectNamesReserved; 14: FederationSaved's and FederationRestored's
// reason, AbortFederationSave, AbortFederationRestore and the transportation queries and reports; 15:
// SubscriptionRate; 16: JoinFederation's fom_modules (FOM modules added at join) and FomExtended; 17: several
// regions (IEEE 1516-2010): AssociateRegion's adds, UnassociateRegion's attributes, SendInteractionWithRegion's
// regions; 18: JoinFederation's federate_type; 19: HLA 4's directed interactions (PublishDirectedInteractions ...
// ReceiveDirectedInteraction) and InitiateFederateRestore's directed declarations
constexpr std::uint16_t kProtocolVersion = 19;
// The default frame limit (the gateway's is configurable and announced in its Welcome): larger frames are a
// protocol error.
constexpr std::uint32_t kMaxFrameBytes = 64u << 20;

// The list that fixes each message's wire code (its position, from 1). Append only.
#define HLACORE_MESSAGES(X)          \
    /* handshake */                  \
    X(Hello)                         \
    X(Welcome)                       \
    /* federate -> gateway */        \
    X(CreateFederation)              \
    X(DestroyFederation)             \
    X(JoinFederation)                \
    X(ResignFederation)              \
    X(RegisterSyncPoint)             \
    X(SyncPointAchieved)             \
    X(PublishObjectClass)            \
    X(UnpublishObjectClass)          \
    X(SubscribeObjectClass)          \
    X(UnsubscribeObjectClass)        \
    X(PublishInteractionClass)       \
    X(UnpublishInteractionClass)     \
    X(SubscribeInteractionClass)     \
    X(UnsubscribeInteractionClass)   \
    X(RegisterObject)                \
    X(UpdateAttributes)              \
    X(SendInteraction)               \
    X(DeleteObject)                  \
    X(LocalDeleteObject)             \
    X(RequestObjectUpdate)           \
    X(RequestClassUpdate)            \
    X(SetAdvisorySwitch)             \
    /* gateway -> federate */        \
    X(Reply)                         \
    X(SyncPointRegistrationSucceeded) \
    X(SyncPointRegistrationFailed)   \
    X(AnnounceSyncPoint)             \
    X(FederationSynchronized)        \
    X(StartRegistration)             \
    X(StopRegistration)              \
    X(TurnInteractionsOn)            \
    X(TurnInteractionsOff)           \
    X(DiscoverObject)                \
    X(ReflectAttributes)             \
    X(ReceiveInteraction)            \
    X(RemoveObject)                  \
    X(ProvideAttributeValueUpdate)   \
    /* time management, both ways */ \
    X(EnableTimeRegulation)          \
    X(DisableTimeRegulation)         \
    X(EnableTimeConstrained)         \
    X(DisableTimeConstrained)        \
    X(TimeAdvance)                   \
    X(ModifyLookahead)               \
    X(SetAsynchronousDelivery)       \
    X(Retract)                       \
    X(QueryTime)                     \
    X(TimeRegulationEnabled)         \
    X(TimeConstrainedEnabled)        \
    X(TimeAdvanceGrant)              \
    X(RequestRetraction)             \
    /* introspection */              \
    X(QueryStatus)                   \
    /* ownership management (HLA 1.3 §7): federate -> gateway */ \
    X(UnconditionalDivestiture)      \
    X(NegotiatedDivestiture)         \
    X(CancelNegotiatedDivestiture)   \
    X(OwnershipAcquisition)          \
    X(OwnershipAcquisitionIfAvailable) \
    X(CancelOwnershipAcquisition)    \
    X(ReleaseResponse)               \
    X(QueryOwnership)                \
    /* ownership management: gateway -> federate */ \
    X(RequestOwnershipAssumption)    \
    X(DivestitureNotification)       \
    X(AcquisitionNotification)       \
    X(OwnershipUnavailable)          \
    X(RequestOwnershipRelease)       \
    X(ConfirmAcquisitionCancellation) \
    X(OwnershipInformation)          \
    /* transport and order changes (HLA 1.3 §6.19-6.22): federate -> gateway */ \
    X(ChangeAttributeDelivery)       \
    X(ChangeInteractionDelivery)     \
    /* save/restore (HLA 1.3 §4.11-4.22): federate -> gateway */ \
    X(RequestFederationSave)         \
    X(FederateSaveComplete)          \
    X(RequestFederationRestore)      \
    X(FederateRestoreComplete)       \
    /* save/restore: gateway -> federate */ \
    X(InitiateFederateSave)          \
    X(FederationSaved)               \
    X(RestoreRequestAnswer)          \
    X(FederationRestoreBegun)        \
    X(InitiateFederateRestore)       \
    X(FederationRestored)            \
    /* data distribution management (HLA 1.3 §9): federate -> gateway */ \
    X(CreateRegion)                  \
    X(ModifyRegion)                  \
    X(DeleteRegion)                  \
    X(RegisterObjectWithRegion)      \
    X(AssociateRegion)               \
    X(UnassociateRegion)             \
    X(SubscribeObjectClassWithRegion) \
    X(UnsubscribeObjectClassWithRegion) \
    X(SubscribeInteractionClassWithRegion) \
    X(UnsubscribeInteractionClassWithRegion) \
    X(SendInteractionWithRegion)     \
    X(RequestClassUpdateWithRegion)  \
    /* data distribution management: gateway -> federate */ \
    X(AttributesInScope)             \
    X(AttributesOutOfScope)          \
    X(TurnUpdatesOn)                 \
    X(TurnUpdatesOff)                \
    /* liveness: federate -> gateway, and the answer */ \
    X(Ping)                          \
    X(Pong)                          \
    /* access control: federate -> gateway, and the answer */ \
    X(Authenticate)                  \
    X(Authenticated)                 \
    /* clock offset to the gateway: federate -> gateway, and the answer */ \
    X(ClockProbe)                    \
    X(ClockEcho)                     \
    /* best effort over UDP (wire/datagram.hpp): a datagram each way, then federate -> gateway */ \
    X(DatagramHello)                 \
    X(DatagramPath)                  \
    /* the results of requests: gateway -> federate (a refusal is a Reply) */ \
    X(FederationJoined)              \
    X(ObjectRegistered)              \
    X(AttributesReleased)            \
    X(StatusReport)                  \
    X(TimeQueried)                   \
    /* the recorder federate (python -m hlacore.record): federate -> gateway, then the records */ \
    X(StartRecording)                \
    X(RecordedTopic)                 \
    X(Recorded)                      \
    /* object instance names (IEEE 1516-2010 §6.2-6.7): federate -> gateway, and the answer */ \
    X(ReserveObjectNames)            \
    X(ReleaseObjectNames)            \
    X(ObjectNamesReserved)           \
    /* IEEE 1516-2010's aborts of a save or a restore: federate -> gateway */ \
    X(AbortFederationSave)           \
    X(AbortFederationRestore)        \
    /* IEEE 1516-2010's transportation queries: federate -> gateway, and the reports */ \
    X(QueryAttributeTransportation)  \
    X(QueryInteractionTransportation) \
    X(AttributeTransportationReported) \
    X(InteractionTransportationReported) \
    /* IEEE 1516-2010's update rate of a subscription: federate -> gateway */ \
    X(SubscriptionRate)              \
    /* FOM modules added at join (IEEE 1516-2010 §4.5): gateway -> the federates joined before */ \
    X(FomExtended)                   \
    /* HLA 4's directed interactions: federate -> gateway, and the callback */ \
    X(PublishDirectedInteractions)   \
    X(SubscribeDirectedInteractions) \
    X(SendDirectedInteraction)       \
    X(ReceiveDirectedInteraction)

// The federate -> gateway messages the gateway serves itself: federation management and the requests
// answered with a Reply or a result. Each has a `Gateway::serve(Connection&, const M&)` in
// cpp/rti/server/ (federations.cpp, session.cpp, status.cpp, datagrams.cpp), declared from this list.
#define HLACORE_GATEWAY_SERVICES(X)                                                                    \
    X(CreateFederation) X(DestroyFederation) X(JoinFederation) X(ResignFederation) X(RegisterObject)   \
    X(RegisterObjectWithRegion) X(RequestFederationSave) X(RequestFederationRestore) X(ReleaseResponse) \
    X(QueryStatus) X(QueryTime) X(Ping) X(Authenticate) X(ClockProbe) X(DatagramPath) X(StartRecording) \
    X(AbortFederationSave) X(AbortFederationRestore)

// The gateway's answers to requests, each echoing the request's id in `request`: a Reply, or the result of a
// request that has one. The client files them apart from callbacks, for the caller waiting on that id.
#define HLACORE_ANSWERS(X) \
    X(Reply) X(FederationJoined) X(ObjectRegistered) X(AttributesReleased) X(StatusReport) X(TimeQueried)

// The requests of a joined federate that its Federation serves, by service group: each has a handler
// `Federation::on(FederateHandle, const M&)` in cpp/rti/server/<group>.cpp, declared from this list.
#define HLACORE_FEDERATION_SERVICES(X)                                                                 \
    /* sync_points (forwarded to SyncPoints by federation.cpp) */                                      \
    X(RegisterSyncPoint) X(SyncPointAchieved)                                                          \
    /* save_restore */                                                                                 \
    X(FederateSaveComplete) X(FederateRestoreComplete)                                                 \
    /* declarations */                                                                                 \
    X(PublishObjectClass) X(UnpublishObjectClass) X(SubscribeObjectClass) X(UnsubscribeObjectClass)    \
    X(PublishInteractionClass) X(UnpublishInteractionClass) X(SubscribeInteractionClass)               \
    X(UnsubscribeInteractionClass) X(SetAdvisorySwitch) X(SubscriptionRate)                            \
    /* objects */                                                                                      \
    X(UpdateAttributes) X(SendInteraction) X(DeleteObject) X(LocalDeleteObject) X(RequestObjectUpdate) \
    X(RequestClassUpdate) X(ChangeAttributeDelivery) X(ChangeInteractionDelivery)                      \
    X(ReserveObjectNames) X(ReleaseObjectNames) X(QueryAttributeTransportation)                        \
    X(QueryInteractionTransportation)                                                                  \
    /* ownership */                                                                                    \
    X(UnconditionalDivestiture) X(NegotiatedDivestiture) X(CancelNegotiatedDivestiture)                \
    X(OwnershipAcquisition) X(OwnershipAcquisitionIfAvailable) X(CancelOwnershipAcquisition)           \
    X(QueryOwnership)                                                                                  \
    /* time */                                                                                         \
    X(EnableTimeRegulation) X(DisableTimeRegulation) X(EnableTimeConstrained) X(DisableTimeConstrained) \
    X(TimeAdvance) X(ModifyLookahead) X(SetAsynchronousDelivery) X(Retract)                            \
    /* regions */                                                                                      \
    X(CreateRegion) X(ModifyRegion) X(DeleteRegion) X(AssociateRegion) X(UnassociateRegion)            \
    X(SubscribeObjectClassWithRegion) X(UnsubscribeObjectClassWithRegion)                              \
    X(SubscribeInteractionClassWithRegion) X(UnsubscribeInteractionClassWithRegion)                    \
    X(SendInteractionWithRegion) X(RequestClassUpdateWithRegion)                                       \
    /* directed */                                                                                     \
    X(PublishDirectedInteractions) X(SubscribeDirectedInteractions) X(SendDirectedInteraction)

// The requests whose federate side is a check followed by the send: each has a
// `void Client::check(const M&)` in cpp/rti/client/<group>.cpp (the service's checks and the federate's own
// state change, under the client's lock), declared from this list; the binding sends one with
// `request<M>` (cpp/bindings/convert.hpp) through `Client::request`.
#define HLACORE_CLIENT_REQUESTS(X)                                                                     \
    /* sync_points */                                                                                  \
    X(RegisterSyncPoint) X(SyncPointAchieved)                                                          \
    /* declarations */                                                                                 \
    X(SubscribeObjectClass) X(UnsubscribeObjectClass) X(PublishInteractionClass)                       \
    X(UnpublishInteractionClass) X(SubscribeInteractionClass) X(UnsubscribeInteractionClass)           \
    X(SetAdvisorySwitch) X(SubscriptionRate)                                                           \
    /* objects */                                                                                      \
    X(LocalDeleteObject) X(RequestObjectUpdate) X(RequestClassUpdate) X(ReserveObjectNames)            \
    X(ReleaseObjectNames) X(QueryAttributeTransportation) X(QueryInteractionTransportation)            \
    /* ownership */                                                                                    \
    X(CancelNegotiatedDivestiture) X(CancelOwnershipAcquisition) X(QueryOwnership)                     \
    /* regions */                                                                                      \
    X(AssociateRegion) X(UnassociateRegion) X(SubscribeObjectClassWithRegion)                          \
    X(UnsubscribeObjectClassWithRegion) X(SubscribeInteractionClassWithRegion)                         \
    X(UnsubscribeInteractionClassWithRegion) X(RequestClassUpdateWithRegion)

// What a federate's client does when a message from the gateway is filed (under its lock, before tick()): each
// has a `bool Client::arrived(M&)` (false: not a callback, tick() never sees it) in client/<group>.cpp,
// declared from this list; the answers (HLACORE_ANSWERS) go to the caller waiting on their id. Any other
// message is a callback, queued as it is.
#define HLACORE_CLIENT_ARRIVALS(X)                                                                     \
    /* the session (client/reader.cpp) */                                                              \
    X(Welcome) X(Authenticated) X(ClockEcho) X(Pong) X(RecordedTopic) X(Recorded)                      \
    /* objects, sync_points: what later calls check against, known at once */                          \
    X(DiscoverObject) X(RemoveObject) X(AnnounceSyncPoint) X(FederationSynchronized)                   \
    /* federation (client.cpp): the FOM that later lookups use, known at once */                       \
    X(FomExtended)

// The callbacks whose delivery changes the federate's own state (HLA 1.3: when tick() hands them over, not
// when they arrive): each has a `void Client::delivered(const M&)` in client/<group>.cpp, declared from this
// list.
#define HLACORE_CLIENT_DELIVERIES(X)                                                                   \
    /* time */                                                                                         \
    X(TimeRegulationEnabled) X(TimeConstrainedEnabled) X(TimeAdvanceGrant)                             \
    /* ownership */                                                                                    \
    X(AcquisitionNotification) X(DivestitureNotification) X(OwnershipUnavailable)                      \
    X(RequestOwnershipRelease) X(ConfirmAcquisitionCancellation)                                       \
    /* save_restore */                                                                                 \
    X(InitiateFederateSave) X(FederationSaved) X(FederationRestoreBegun) X(FederationRestored)         \
    X(InitiateFederateRestore)

enum class MessageType : std::uint16_t { HLACORE_LIST_CODES(Invalid, HLACORE_MESSAGES) };

const char* message_name(MessageType type);

// Declares the fields in wire order, for the codec to visit (const and mutable).
// Their names, comma-separated, are for the recording's JSON (rti/wire/json.hpp).
#define HLACORE_FIELDS(...)                                  \
    static constexpr const char* kFieldNames = #__VA_ARGS__; \
    template <class F>                                       \
    void fields(F&& f) { f(__VA_ARGS__); }                   \
    template <class F>                                       \
    void fields(F&& f) const { f(__VA_ARGS__); }
#define HLACORE_NO_FIELDS()                        \
    static constexpr const char* kFieldNames = ""; \
    template <class F>                             \
    void fields(F&&) {}                            \
    template <class F>                             \
    void fields(F&&) const {}
#define HLACORE_TYPE(name) static constexpr MessageType kType = MessageType::name;

}  // namespace hlacore::wire
