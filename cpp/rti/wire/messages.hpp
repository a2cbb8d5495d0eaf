// The wire protocol: every message exchanged between a federate and the gateway, declared once in the order
// of message_list.hpp; codec.hpp encodes and decodes them (messages.cpp: names, framing). No sockets
// here.
//
// A frame on the socket is: u32 length (little-endian, counts what follows), u16 message type, payload.
// The payload is the message's fields in declaration order, encoded as codec.hpp says.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "rti/wire/message_list.hpp"
#include "rti/wire/value.hpp"

namespace hlacore::wire {

using Handles = std::vector<std::uint32_t>;
using HandleValue = std::pair<std::uint32_t, Value>;
using HandleValues = std::vector<HandleValue>;
// The values of an update or interaction as the gateway serves them: views into the frame being served, not
// copies (a camera frame is megabytes); HandleValues on the wire.
using HandleValueView = std::pair<std::uint32_t, std::string_view>;
using HandleValueViews = std::vector<HandleValueView>;
// ... and as it forwards them to each receiver: pointers to those, not copies per receiver.
using HandleValueRefs = std::vector<const HandleValueView*>;
inline HandleValueViews views_of(const HandleValues& values) {
    return HandleValueViews(values.begin(), values.end());
}
using OptionalTime = std::optional<double>;

// Resign actions, with PyHLA's values.
enum class ResignAction : std::uint8_t {
    ReleaseAttributes = 1,
    DeleteObjects = 2,
    DeleteObjectsAndReleaseAttributes = 3,
    NoAction = 4,
};

enum class AdvisorySwitch : std::uint8_t { ClassRelevance = 1, AttributeRelevance, AttributeScope, InteractionRelevance };

// A nested record kept on the heap, so that a large message does not make every wire::Message (a std::variant)
// as large as it. Copies share the record; edit() copies it first if it is shared.
template <class T>
class Boxed {
public:
    Boxed() : p_(std::make_shared<T>()) {}
    const T& operator*() const { return *p_; }
    const T* operator->() const { return p_.get(); }
    T& edit() {
        if (p_.use_count() > 1) p_ = std::make_shared<T>(*p_);
        return *p_;
    }

private:
    std::shared_ptr<T> p_;
};

// ---- handshake ----
struct Hello {
    HLACORE_TYPE(Hello)
    std::uint32_t magic = kMagic;
    std::uint16_t version = kProtocolVersion;
    HLACORE_FIELDS(magic, version)
};
struct Welcome {
    HLACORE_TYPE(Welcome)
    std::uint16_t version = kProtocolVersion;
    std::string server;
    std::uint32_t max_frame_bytes = kMaxFrameBytes;  // the gateway's frame limit, both directions
    std::string challenge;  // non-empty: the client must send Authenticate before anything else (rti/auth.hpp)
    // Best effort over UDP (wire/datagram.hpp), on the gateway's port: the token of this connection's datagrams
    // (0: the gateway takes none) and the largest datagram either side sends.
    std::uint64_t datagram_token = 0;
    std::uint32_t max_datagram = 0;
    // Non-empty when some federation has a secret of its own: what this connection's federation proofs sign.
    std::string nonce;
    HLACORE_FIELDS(version, server, max_frame_bytes, challenge, datagram_token, max_datagram, nonce)
};
struct Authenticate {
    HLACORE_TYPE(Authenticate)
    std::string proof;  // auth::proof(secret, challenge)
    HLACORE_FIELDS(proof)
};
// NTP-style: the gateway stamps a probe with its steady clock (CLOCK_MONOTONIC on Linux, nanoseconds), so a
// client that also knows when it sent and got it back bounds the offset between the two clocks.
struct ClockProbe {
    HLACORE_TYPE(ClockProbe)
    std::uint32_t sequence = 0;
    std::uint64_t client_ns = 0;  // when the client sent it, on its steady clock
    HLACORE_FIELDS(sequence, client_ns)
};
struct ClockEcho {
    HLACORE_TYPE(ClockEcho)
    std::uint32_t sequence = 0;
    std::uint64_t client_ns = 0;   // the probe's
    std::uint64_t gateway_ns = 0;  // when the gateway answered, on its steady clock
    HLACORE_FIELDS(sequence, client_ns, gateway_ns)
};
// The only frame of a datagram that is not a best-effort message: the client's first datagrams, and the
// gateway's echo of each, which shows the client that datagrams get through both ways.
struct DatagramHello {
    HLACORE_TYPE(DatagramHello)
    std::uint32_t attempt = 0;
    HLACORE_FIELDS(attempt)
};
// Over the stream, once the client got the gateway's echo: the gateway may send it best-effort messages as
// datagrams from now on.
struct DatagramPath {
    HLACORE_TYPE(DatagramPath)
    HLACORE_NO_FIELDS()
};
struct Authenticated {
    HLACORE_TYPE(Authenticated)
    bool accepted = false;
    std::string reason;  // when refused; the gateway closes the connection after it
    HLACORE_FIELDS(accepted, reason)
};

// ---- liveness: a client that has heard nothing for a while asks; the gateway answers at once, joined or not ----
struct Ping {
    HLACORE_TYPE(Ping)
    std::uint32_t sequence = 0;
    HLACORE_FIELDS(sequence)
};
struct Pong {
    HLACORE_TYPE(Pong)
    std::uint32_t sequence = 0;
    HLACORE_FIELDS(sequence)
};

// ---- federate -> gateway; `request` ids are echoed in the answer (HLACORE_ANSWERS) ----
struct CreateFederation {
    HLACORE_TYPE(CreateFederation)
    std::uint32_t request = 0;
    std::uint8_t time_semantics = 0;  // TimeSemantics (rti/time.hpp); 0: the gateway's --time-semantics
    std::uint8_t time_type = 0;       // TimeType (rti/time.hpp)
    std::string federation;
    std::string fed_name;  // as given by the caller
    std::string fed_text;  // a .fed, an XML module or a bundle of modules; empty: the gateway looks fed_name up
    std::string proof;     // auth::federation_proof(secret, nonce, "create", federation); empty: none
    HLACORE_FIELDS(request, federation, fed_name, fed_text, proof, time_semantics, time_type)
};
struct DestroyFederation {
    HLACORE_TYPE(DestroyFederation)
    std::uint32_t request = 0;
    std::string federation;
    std::string proof;  // as CreateFederation's, for "destroy"
    HLACORE_FIELDS(request, federation, proof)
};
// What a federate adds to its join beyond its name (a record on the heap: Boxed).
struct Joining {
    // FOM modules this federate adds to the federation's (IEEE 1516-2010 §4.5), as a bundle of modules
    // (fom::bundle); empty: none. The gateway refuses the join when they do not read or do not fit.
    std::string fom_modules;
    std::string federate_type;  // IEEE 1516-2010's (HLA 1.3 has none: ""), for the status report
    HLACORE_FIELDS(fom_modules, federate_type)
};
struct JoinFederation {
    HLACORE_TYPE(JoinFederation)
    std::uint32_t request = 0;
    std::string federate;
    std::string federation;
    std::string proof;  // as CreateFederation's, for "join"
    Boxed<Joining> joining;
    HLACORE_FIELDS(request, federate, federation, proof, joining)
};
struct ResignFederation {
    HLACORE_TYPE(ResignFederation)
    std::uint32_t request = 0;
    std::uint8_t action = 0;
    HLACORE_FIELDS(request, action)
};
struct RegisterSyncPoint {
    HLACORE_TYPE(RegisterSyncPoint)
    std::string label;
    std::string tag;
    bool whole_federation = true;
    Handles federates;  // used when !whole_federation
    HLACORE_FIELDS(label, tag, whole_federation, federates)
};
struct SyncPointAchieved {
    HLACORE_TYPE(SyncPointAchieved)
    std::string label;
    HLACORE_FIELDS(label)
};
struct PublishObjectClass {
    HLACORE_TYPE(PublishObjectClass)
    std::uint32_t object_class = 0;
    Handles attributes;
    HLACORE_FIELDS(object_class, attributes)
};
struct UnpublishObjectClass {
    HLACORE_TYPE(UnpublishObjectClass)
    std::uint32_t object_class = 0;
    HLACORE_FIELDS(object_class)
};
struct SubscribeObjectClass {
    HLACORE_TYPE(SubscribeObjectClass)
    std::uint32_t object_class = 0;
    Handles attributes;
    bool active = true;
    HLACORE_FIELDS(object_class, attributes, active)
};
// IEEE 1516-2010: the update rate a class's subscription asks for, named as the FOM names it ("": none), sent
// before the subscription; it holds for the class's attributes until the next one.
struct SubscriptionRate {
    HLACORE_TYPE(SubscriptionRate)
    std::uint32_t object_class = 0;
    std::string designator;
    HLACORE_FIELDS(object_class, designator)
};
struct UnsubscribeObjectClass {
    HLACORE_TYPE(UnsubscribeObjectClass)
    std::uint32_t object_class = 0;
    HLACORE_FIELDS(object_class)
};
struct PublishInteractionClass {
    HLACORE_TYPE(PublishInteractionClass)
    std::uint32_t interaction_class = 0;
    HLACORE_FIELDS(interaction_class)
};
struct UnpublishInteractionClass {
    HLACORE_TYPE(UnpublishInteractionClass)
    std::uint32_t interaction_class = 0;
    HLACORE_FIELDS(interaction_class)
};
struct SubscribeInteractionClass {
    HLACORE_TYPE(SubscribeInteractionClass)
    std::uint32_t interaction_class = 0;
    bool active = true;
    HLACORE_FIELDS(interaction_class, active)
};
struct UnsubscribeInteractionClass {
    HLACORE_TYPE(UnsubscribeInteractionClass)
    std::uint32_t interaction_class = 0;
    HLACORE_FIELDS(interaction_class)
};
struct RegisterObject {
    HLACORE_TYPE(RegisterObject)
    std::uint32_t request = 0;
    std::uint32_t object_class = 0;
    std::string name;  // empty: the gateway picks a unique one
    HLACORE_FIELDS(request, object_class, name)
};
// Values: HandleValues, or HandleValueViews for the gateway (UpdateAttributesView): the same frame.
template <class Values>
struct BasicUpdateAttributes {
    HLACORE_TYPE(UpdateAttributes)
    std::uint32_t object = 0;
    Values values;
    std::string tag;
    OptionalTime time;
    std::uint64_t serial = 0;  // with the sender's handle, the event retraction handle
    HLACORE_FIELDS(object, values, tag, time, serial)
};
using UpdateAttributes = BasicUpdateAttributes<HandleValues>;
using UpdateAttributesView = BasicUpdateAttributes<HandleValueViews>;
template <class Values>
struct BasicSendInteraction {
    HLACORE_TYPE(SendInteraction)
    std::uint32_t interaction_class = 0;
    Values values;
    std::string tag;
    OptionalTime time;
    std::uint64_t serial = 0;
    HLACORE_FIELDS(interaction_class, values, tag, time, serial)
};
using SendInteraction = BasicSendInteraction<HandleValues>;
using SendInteractionView = BasicSendInteraction<HandleValueViews>;
struct DeleteObject {
    HLACORE_TYPE(DeleteObject)
    std::uint32_t object = 0;
    std::string tag;
    OptionalTime time;
    std::uint64_t serial = 0;
    HLACORE_FIELDS(object, tag, time, serial)
};
struct LocalDeleteObject {
    HLACORE_TYPE(LocalDeleteObject)
    std::uint32_t object = 0;
    HLACORE_FIELDS(object)
};
struct RequestObjectUpdate {
    HLACORE_TYPE(RequestObjectUpdate)
    std::uint32_t object = 0;
    Handles attributes;
    HLACORE_FIELDS(object, attributes)
};
struct RequestClassUpdate {
    HLACORE_TYPE(RequestClassUpdate)
    std::uint32_t object_class = 0;
    Handles attributes;
    HLACORE_FIELDS(object_class, attributes)
};
struct SetAdvisorySwitch {
    HLACORE_TYPE(SetAdvisorySwitch)
    std::uint8_t which = 0;  // AdvisorySwitch
    bool on = true;
    HLACORE_FIELDS(which, on)
};

// ---- time management (HLA 1.3 §8) ----
struct EnableTimeRegulation {
    HLACORE_TYPE(EnableTimeRegulation)
    double time = 0;
    double lookahead = 0;
    HLACORE_FIELDS(time, lookahead)
};
struct DisableTimeRegulation {
    HLACORE_TYPE(DisableTimeRegulation)
    HLACORE_NO_FIELDS()
};
struct EnableTimeConstrained {
    HLACORE_TYPE(EnableTimeConstrained)
    HLACORE_NO_FIELDS()
};
struct DisableTimeConstrained {
    HLACORE_TYPE(DisableTimeConstrained)
    HLACORE_NO_FIELDS()
};
struct TimeAdvance {
    HLACORE_TYPE(TimeAdvance)
    std::uint8_t kind = 0;  // AdvanceKind: TAR, TARA, NER, NERA, FQR
    double time = 0;
    HLACORE_FIELDS(kind, time)
};
struct ModifyLookahead {
    HLACORE_TYPE(ModifyLookahead)
    double lookahead = 0;
    HLACORE_FIELDS(lookahead)
};
struct SetAsynchronousDelivery {
    HLACORE_TYPE(SetAsynchronousDelivery)
    bool on = false;
    HLACORE_FIELDS(on)
};
struct Retract {
    HLACORE_TYPE(Retract)
    std::uint64_t serial = 0;
    HLACORE_FIELDS(serial)
};
enum class TimeQuery : std::uint8_t { Lbts = 1, MinNextEventTime = 2 };
struct QueryTime {
    HLACORE_TYPE(QueryTime)
    std::uint32_t request = 0;
    std::uint8_t which = 0;  // TimeQuery
    HLACORE_FIELDS(request, which)
};

// Answered with a StatusReport; allowed before joining, so that `rtig --status` can ask.
struct QueryStatus {
    HLACORE_TYPE(QueryStatus)
    std::uint32_t request = 0;
    std::uint64_t events_after = 0;  // the report's event log holds only those numbered above this
    bool instances = true;           // list every object instance with its owners (hlacore.monitor does not)
    HLACORE_FIELDS(request, events_after, instances)
};

// ---- gateway -> federate ----
// The answer to a request without a result, and the refusal (error != 0) of any request.
struct Reply {
    HLACORE_TYPE(Reply)
    std::uint32_t request = 0;
    std::uint16_t error = 0;  // ErrorCode, 0 = success
    std::string message;      // the exception's reason when error != 0
    HLACORE_FIELDS(request, error, message)
};
// Object instance names (IEEE 1516-2010 §6.2-6.7): reserved for the asking federate until it registers an
// object with one, releases it or leaves.
struct ReserveObjectNames {
    HLACORE_TYPE(ReserveObjectNames)
    bool multiple = false;  // reserveMultipleObjectInstanceName: all of them or none
    std::vector<std::string> names;
    HLACORE_FIELDS(multiple, names)
};
struct ReleaseObjectNames {
    HLACORE_TYPE(ReleaseObjectNames)
    std::vector<std::string> names;
    HLACORE_FIELDS(names)
};
struct ObjectNamesReserved {  // the answer, a callback
    HLACORE_TYPE(ObjectNamesReserved)
    bool multiple = false;
    bool success = false;
    std::vector<std::string> names;
    HLACORE_FIELDS(multiple, success, names)
};
// The results of requests, one message each.
struct FederationJoined {  // JoinFederation
    HLACORE_TYPE(FederationJoined)
    std::uint32_t request = 0;
    std::uint32_t federate = 0;  // the joined federate's handle
    std::uint8_t time_type = 0;  // the federation's TimeType
    std::string fed_text;        // the federation's FOM (a .fed, an XML module or a bundle), which the client parses
    std::string fed_name;        // its name, as given at creation
    HLACORE_FIELDS(request, federate, fed_text, fed_name, time_type)
};
// A federate joined with FOM modules of its own: the federation's FOM is now `fed_text` (a bundle marking the
// added modules, fed_parser/omt.hpp), every handle of the FOM before kept. The federates joined before take it
// in place of theirs as it arrives, before anything that uses the new classes can.
struct FomExtended {
    HLACORE_TYPE(FomExtended)
    std::string fed_text;
    std::string fed_name;  // as given at creation
    HLACORE_FIELDS(fed_text, fed_name)
};
struct ObjectRegistered {  // RegisterObject, RegisterObjectWithRegion
    HLACORE_TYPE(ObjectRegistered)
    std::uint32_t request = 0;
    std::uint32_t object = 0;
    std::string name;  // as asked, or the one the gateway picked
    HLACORE_FIELDS(request, object, name)
};
struct AttributesReleased {  // ReleaseResponse: the attributes actually released
    HLACORE_TYPE(AttributesReleased)
    std::uint32_t request = 0;
    Handles attributes;
    HLACORE_FIELDS(request, attributes)
};
struct StatusReport {  // QueryStatus: the gateway's state as JSON (what `rtig --status` prints, hlacore/status.py)
    HLACORE_TYPE(StatusReport)
    std::uint32_t request = 0;
    std::string json;
    HLACORE_FIELDS(request, json)
};
struct TimeQueried {  // QueryTime
    HLACORE_TYPE(TimeQueried)
    std::uint32_t request = 0;
    double time = 0;
    HLACORE_FIELDS(request, time)
};
// The recorder federate (python -m hlacore.record): StartRecording (answered with a Reply) makes the
// gateway send the joined federate every record of its federation's recording (server/recorder.hpp) as
// Recorded (each topic announced first by a RecordedTopic), beginning with the FOM and the federates joined
// so far; the client writes them into an MCAP file.
struct StartRecording {
    HLACORE_TYPE(StartRecording)
    std::uint32_t request = 0;
    HLACORE_FIELDS(request)
};
struct RecordedTopic {
    HLACORE_TYPE(RecordedTopic)
    std::string topic;
    std::string schema_name;
    std::string schema;  // the topic's JSON schema
    HLACORE_FIELDS(topic, schema_name, schema)
};
struct Recorded {
    HLACORE_TYPE(Recorded)
    std::string topic;
    std::uint32_t sequence = 0;
    std::uint64_t log_ns = 0;
    std::string data;  // the JSON message
    HLACORE_FIELDS(topic, sequence, log_ns, data)
};
struct SyncPointRegistrationSucceeded {
    HLACORE_TYPE(SyncPointRegistrationSucceeded)
    std::string label;
    HLACORE_FIELDS(label)
};
struct SyncPointRegistrationFailed {
    HLACORE_TYPE(SyncPointRegistrationFailed)
    std::string label;
    HLACORE_FIELDS(label)
};
struct AnnounceSyncPoint {
    HLACORE_TYPE(AnnounceSyncPoint)
    std::string label;
    std::string tag;
    HLACORE_FIELDS(label, tag)
};
struct FederationSynchronized {
    HLACORE_TYPE(FederationSynchronized)
    std::string label;
    HLACORE_FIELDS(label)
};
struct StartRegistration {
    HLACORE_TYPE(StartRegistration)
    std::uint32_t object_class = 0;
    HLACORE_FIELDS(object_class)
};
struct StopRegistration {
    HLACORE_TYPE(StopRegistration)
    std::uint32_t object_class = 0;
    HLACORE_FIELDS(object_class)
};
struct TurnInteractionsOn {
    HLACORE_TYPE(TurnInteractionsOn)
    std::uint32_t interaction_class = 0;
    HLACORE_FIELDS(interaction_class)
};
struct TurnInteractionsOff {
    HLACORE_TYPE(TurnInteractionsOff)
    std::uint32_t interaction_class = 0;
    HLACORE_FIELDS(interaction_class)
};
struct DiscoverObject {
    HLACORE_TYPE(DiscoverObject)
    std::uint32_t object = 0;
    std::uint32_t object_class = 0;  // the class the receiver knows it as
    std::string name;
    HLACORE_FIELDS(object, object_class, name)
};
// What the gateway adds to an update or interaction it forwards (ReflectAttributes, ReceiveInteraction:
// order, transport, sender): a sender keeps its frame this much under the limit so that they always fit.
constexpr std::size_t kForwardedGrowth = 1 + 1 + 4;
// Values: HandleValues, or HandleValueRefs for the gateway's forwarding (ForwardedReflection): the same frame.
template <class Values>
struct BasicReflectAttributes {
    HLACORE_TYPE(ReflectAttributes)
    std::uint32_t object = 0;
    Values values;
    std::string tag;
    std::uint8_t order = 1;      // fom::Order
    std::uint8_t transport = 1;  // fom::Transport
    OptionalTime time;
    std::uint32_t sender = 0;
    std::uint64_t serial = 0;
    HLACORE_FIELDS(object, values, tag, order, transport, time, sender, serial)
};
using ReflectAttributes = BasicReflectAttributes<HandleValues>;
using ForwardedReflection = BasicReflectAttributes<HandleValueRefs>;
template <class Values>
struct BasicReceiveInteraction {
    HLACORE_TYPE(ReceiveInteraction)
    std::uint32_t interaction_class = 0;
    Values values;
    std::string tag;
    std::uint8_t order = 1;
    std::uint8_t transport = 1;
    OptionalTime time;
    std::uint32_t sender = 0;
    std::uint64_t serial = 0;
    HLACORE_FIELDS(interaction_class, values, tag, order, transport, time, sender, serial)
};
using ReceiveInteraction = BasicReceiveInteraction<HandleValues>;
using ForwardedInteraction = BasicReceiveInteraction<HandleValueRefs>;
struct RemoveObject {
    HLACORE_TYPE(RemoveObject)
    std::uint32_t object = 0;
    std::string tag;
    OptionalTime time;
    std::uint32_t sender = 0;
    std::uint64_t serial = 0;
    HLACORE_FIELDS(object, tag, time, sender, serial)
};
struct ProvideAttributeValueUpdate {
    HLACORE_TYPE(ProvideAttributeValueUpdate)
    std::uint32_t object = 0;
    Handles attributes;
    HLACORE_FIELDS(object, attributes)
};

struct TimeRegulationEnabled {
    HLACORE_TYPE(TimeRegulationEnabled)
    double time = 0;
    HLACORE_FIELDS(time)
};
struct TimeConstrainedEnabled {
    HLACORE_TYPE(TimeConstrainedEnabled)
    double time = 0;
    HLACORE_FIELDS(time)
};
struct TimeAdvanceGrant {
    HLACORE_TYPE(TimeAdvanceGrant)
    double time = 0;
    HLACORE_FIELDS(time)
};
struct RequestRetraction {
    HLACORE_TYPE(RequestRetraction)
    std::uint32_t sender = 0;
    std::uint64_t serial = 0;
    HLACORE_FIELDS(sender, serial)
};

// ---- ownership management (HLA 1.3 §7) ----
// Federate -> gateway. The gateway acts only where its state agrees (the client checks the exceptions):
// a transfer may already be on its way to a federate that has not yet evoked the notification.
struct UnconditionalDivestiture {
    HLACORE_TYPE(UnconditionalDivestiture)
    std::uint32_t object = 0;
    Handles attributes;
    HLACORE_FIELDS(object, attributes)
};
struct NegotiatedDivestiture {
    HLACORE_TYPE(NegotiatedDivestiture)
    std::uint32_t object = 0;
    Handles attributes;
    std::string tag;
    HLACORE_FIELDS(object, attributes, tag)
};
struct CancelNegotiatedDivestiture {
    HLACORE_TYPE(CancelNegotiatedDivestiture)
    std::uint32_t object = 0;
    Handles attributes;
    HLACORE_FIELDS(object, attributes)
};
struct OwnershipAcquisition {
    HLACORE_TYPE(OwnershipAcquisition)
    std::uint32_t object = 0;
    Handles attributes;
    std::string tag;
    HLACORE_FIELDS(object, attributes, tag)
};
struct OwnershipAcquisitionIfAvailable {
    HLACORE_TYPE(OwnershipAcquisitionIfAvailable)
    std::uint32_t object = 0;
    Handles attributes;
    HLACORE_FIELDS(object, attributes)
};
struct CancelOwnershipAcquisition {
    HLACORE_TYPE(CancelOwnershipAcquisition)
    std::uint32_t object = 0;
    Handles attributes;
    HLACORE_FIELDS(object, attributes)
};
// Answered with AttributesReleased.
struct ReleaseResponse {
    HLACORE_TYPE(ReleaseResponse)
    std::uint32_t request = 0;
    std::uint32_t object = 0;
    Handles attributes;
    HLACORE_FIELDS(request, object, attributes)
};
struct QueryOwnership {
    HLACORE_TYPE(QueryOwnership)
    std::uint32_t object = 0;
    std::uint32_t attribute = 0;
    HLACORE_FIELDS(object, attribute)
};

// Gateway -> federate.
struct RequestOwnershipAssumption {
    HLACORE_TYPE(RequestOwnershipAssumption)
    std::uint32_t object = 0;
    Handles attributes;
    std::string tag;
    HLACORE_FIELDS(object, attributes, tag)
};
struct DivestitureNotification {
    HLACORE_TYPE(DivestitureNotification)
    std::uint32_t object = 0;
    Handles attributes;
    HLACORE_FIELDS(object, attributes)
};
struct AcquisitionNotification {
    HLACORE_TYPE(AcquisitionNotification)
    std::uint32_t object = 0;
    Handles attributes;
    HLACORE_FIELDS(object, attributes)
};
struct OwnershipUnavailable {
    HLACORE_TYPE(OwnershipUnavailable)
    std::uint32_t object = 0;
    Handles attributes;
    HLACORE_FIELDS(object, attributes)
};
struct RequestOwnershipRelease {
    HLACORE_TYPE(RequestOwnershipRelease)
    std::uint32_t object = 0;
    Handles attributes;
    std::string tag;
    HLACORE_FIELDS(object, attributes, tag)
};
struct ConfirmAcquisitionCancellation {
    HLACORE_TYPE(ConfirmAcquisitionCancellation)
    std::uint32_t object = 0;
    Handles attributes;
    HLACORE_FIELDS(object, attributes)
};
// The answer to QueryOwnership: informAttributeOwnership, attributeIsNotOwned or attributeOwnedByRTI.
enum class OwnershipKind : std::uint8_t { OwnedByFederate = 1, NotOwned = 2, OwnedByRti = 3 };
struct OwnershipInformation {
    HLACORE_TYPE(OwnershipInformation)
    std::uint32_t object = 0;
    std::uint32_t attribute = 0;
    std::uint8_t kind = 0;   // OwnershipKind
    std::uint32_t owner = 0;  // when OwnedByFederate
    HLACORE_FIELDS(object, attribute, kind, owner)
};

// ---- transport and order changes (HLA 1.3 §6.19-6.22) ----
// Federate -> gateway; order and transport are fom::Order / fom::Transport values, 0 = left as it is.
// The gateway applies an attribute's change only while the sender owns it (the client checks the
// exceptions), and forgets it when the object is deleted or the attribute changes owner.
struct ChangeAttributeDelivery {
    HLACORE_TYPE(ChangeAttributeDelivery)
    std::uint32_t object = 0;
    Handles attributes;
    std::uint8_t order = 0;
    std::uint8_t transport = 0;
    HLACORE_FIELDS(object, attributes, order, transport)
};
// For the sender's own interactions of that class, until it unpublishes the class.
struct ChangeInteractionDelivery {
    HLACORE_TYPE(ChangeInteractionDelivery)
    std::uint32_t interaction_class = 0;
    std::uint8_t order = 0;
    std::uint8_t transport = 0;
    HLACORE_FIELDS(interaction_class, order, transport)
};
// IEEE 1516-2010's queries of the transportation in use: an attribute of an object (its owner's change, else
// the FOM's), a federate's interactions of a class (that federate's change, else the FOM's). Each is
// answered by its report, a callback.
struct QueryAttributeTransportation {
    HLACORE_TYPE(QueryAttributeTransportation)
    std::uint32_t object = 0;
    std::uint32_t attribute = 0;
    HLACORE_FIELDS(object, attribute)
};
struct QueryInteractionTransportation {
    HLACORE_TYPE(QueryInteractionTransportation)
    std::uint32_t federate = 0;
    std::uint32_t interaction_class = 0;
    HLACORE_FIELDS(federate, interaction_class)
};
struct AttributeTransportationReported {  // reportAttributeTransportationType
    HLACORE_TYPE(AttributeTransportationReported)
    std::uint32_t object = 0;
    std::uint32_t attribute = 0;
    std::uint8_t transport = 0;
    HLACORE_FIELDS(object, attribute, transport)
};
struct InteractionTransportationReported {  // reportInteractionTransportationType
    HLACORE_TYPE(InteractionTransportationReported)
    std::uint32_t federate = 0;
    std::uint32_t interaction_class = 0;
    std::uint8_t transport = 0;
    HLACORE_FIELDS(federate, interaction_class, transport)
};

// ---- save/restore (HLA 1.3 §4.11-4.22; docs/save-restore.md) ----
// Federate -> gateway. The two requests are answered with a Reply (SaveInProgress, RestoreInProgress,
// FederationTimeAlreadyPassed); the outcome comes as callbacks.
struct RequestFederationSave {
    HLACORE_TYPE(RequestFederationSave)
    std::uint32_t request = 0;
    std::string label;
    OptionalTime time;  // timed save: time-managed federates save at their first grant at or beyond it
    HLACORE_FIELDS(request, label, time)
};
struct FederateSaveComplete {  // federateSaveComplete, or federateSaveNotComplete when !success
    HLACORE_TYPE(FederateSaveComplete)
    bool success = true;
    HLACORE_FIELDS(success)
};
struct RequestFederationRestore {
    HLACORE_TYPE(RequestFederationRestore)
    std::uint32_t request = 0;
    std::string label;
    HLACORE_FIELDS(request, label)
};
struct FederateRestoreComplete {  // federateRestoreComplete, or federateRestoreNotComplete when !success
    HLACORE_TYPE(FederateRestoreComplete)
    bool success = true;
    HLACORE_FIELDS(success)
};

// IEEE 1516-2010: ends the save or restore under way, federationNotSaved or federationNotRestored with the
// reason Aborted at every federate; answered with a Reply (SaveNotInProgress, RestoreNotInProgress).
struct AbortFederationSave {
    HLACORE_TYPE(AbortFederationSave)
    std::uint32_t request = 0;
    HLACORE_FIELDS(request)
};
struct AbortFederationRestore {
    HLACORE_TYPE(AbortFederationRestore)
    std::uint32_t request = 0;
    HLACORE_FIELDS(request)
};

// Gateway -> federate.
struct InitiateFederateSave {
    HLACORE_TYPE(InitiateFederateSave)
    std::string label;
    HLACORE_FIELDS(label)
};
// Why a save or a restore failed, numbered as IEEE 1516-2010's SaveFailureReason and RestoreFailureReason
// (HLA 1.3's federationNotSaved and federationNotRestored do not say).
enum class SaveFailure : std::uint8_t {
    RtiUnable = 0, FederateReported = 1, FederateResigned = 2, RtiDetected = 3, TimeCannotBeHonored = 4, Aborted = 5
};
enum class RestoreFailure : std::uint8_t { RtiUnable = 0, FederateReported = 1, FederateResigned = 2, RtiDetected = 3, Aborted = 4 };
static_assert(static_cast<int>(SaveFailure::FederateResigned) == static_cast<int>(RestoreFailure::FederateResigned) &&
              static_cast<int>(SaveFailure::FederateReported) == static_cast<int>(RestoreFailure::FederateReported));

struct FederationSaved {  // federationSaved, or federationNotSaved(reason) when !success
    HLACORE_TYPE(FederationSaved)
    bool success = true;
    std::uint8_t reason = 0;  // SaveFailure
    HLACORE_FIELDS(success, reason)
};
// requestFederationRestoreSucceeded(label), or requestFederationRestoreFailed(label, reason).
struct RestoreRequestAnswer {
    HLACORE_TYPE(RestoreRequestAnswer)
    std::string label;
    bool succeeded = false;
    std::string reason;
    HLACORE_FIELDS(label, succeeded, reason)
};
struct FederationRestoreBegun {
    HLACORE_TYPE(FederationRestoreBegun)
    HLACORE_NO_FIELDS()
};
// initiateFederateRestore(label, federate), carrying what the client mirrors of the restored federate:
// its handle in the save, time state, declarations and the objects it knows (parallel vectors).

// What a restored federate had in the save, as its client mirrors it (records nested in
// initiateFederateRestore, each encoded as its fields in order).
struct ClassAttributes {  // a published or subscribed object class and its attributes (directed: interactions)
    std::uint32_t object_class = 0;
    Handles attributes;
    HLACORE_FIELDS(object_class, attributes)
};
struct KnownObject {
    std::uint32_t object = 0;
    std::uint32_t known_class = 0;  // the class the federate knows the object as
    std::string name;
    Handles owned;                  // the attributes it owns
    bool may_delete = false;        // it holds the privilege to delete the object
    HLACORE_FIELDS(object, known_class, name, owned, may_delete)
};
struct RegionRecord {  // data distribution management (HLA 1.3 §9): a region under its saved number
    std::uint32_t region = 0;
    std::uint32_t space = 0;
    Handles bounds;
    HLACORE_FIELDS(region, space, bounds)
};
struct RegionSubscription {
    std::uint32_t object_class = 0;
    std::uint32_t region = 0;
    Handles attributes;
    HLACORE_FIELDS(object_class, region, attributes)
};
struct InteractionRegion {
    std::uint32_t interaction_class = 0;
    std::uint32_t region = 0;
    HLACORE_FIELDS(interaction_class, region)
};
struct UpdateRegion {  // a region the federate updates an object's attribute in (several under IEEE 1516-2010)
    std::uint32_t object = 0;
    std::uint32_t attribute = 0;
    std::uint32_t region = 0;
    HLACORE_FIELDS(object, attribute, region)
};
// A federate's time state as a federation save keeps it: the gateway's TimeManager hands it out, the save
// file records it and initiateFederateRestore brings it back to the client. A pending time advance request or
// regulation enable is not part of it: the restored federate is granted at its time.
struct SavedTime {
    double time = 0;
    double lookahead = 0;
    bool regulating = false;
    bool constrained = false;
    bool asynchronous_delivery = false;
    bool strict_after_grant = false;   // last grant was TAR/NER with zero lookahead: sends must be > time
    bool receives_above_time = false;  // last grant was TAR/NER while constrained: nothing at time may arrive
    // No message below this was ever allowed since regulation began (-infinity when not regulating).
    double promise = -std::numeric_limits<double>::infinity();
    HLACORE_FIELDS(time, lookahead, regulating, constrained, asynchronous_delivery, strict_after_grant,
                   receives_above_time, promise)
};
struct RestoredState {
    SavedTime time_state;
    std::uint64_t next_serial = 0;  // serials at or below this are held by restored queues
    std::vector<ClassAttributes> published;
    std::vector<ClassAttributes> subscribed;
    Handles published_interactions;
    Handles subscribed_interactions;
    std::vector<KnownObject> objects;
    std::vector<RegionRecord> regions;
    std::vector<RegionSubscription> region_subscriptions;
    std::vector<InteractionRegion> region_interaction_subscriptions;
    std::vector<UpdateRegion> update_regions;
    std::uint32_t last_region = 0;  // the highest region number this federate ever created
    // HLA 4's directed interactions: object class and interaction classes published, subscribed, universally.
    std::vector<ClassAttributes> published_directed;
    std::vector<ClassAttributes> subscribed_directed;
    std::vector<ClassAttributes> subscribed_directed_universally;
    HLACORE_FIELDS(time_state, next_serial, published, subscribed, published_interactions, subscribed_interactions,
                   objects, regions, region_subscriptions, region_interaction_subscriptions, update_regions, last_region,
                   published_directed, subscribed_directed, subscribed_directed_universally)
};
struct InitiateFederateRestore {
    HLACORE_TYPE(InitiateFederateRestore)
    std::string label;
    std::uint32_t federate = 0;  // the handle the federate had in the save
    Boxed<RestoredState> state;
    HLACORE_FIELDS(label, federate, state)
};
struct FederationRestored {  // federationRestored, or federationNotRestored(reason) when !success
    HLACORE_TYPE(FederationRestored)
    bool success = true;
    std::uint8_t reason = 0;  // RestoreFailure
    HLACORE_FIELDS(success, reason)
};

// ---- data distribution management (HLA 1.3 §9) ----
// Regions belong to the federate that created them; its client picks their handles (1, 2, ...), so the
// gateway keys them by (federate, region) and creating one needs no round trip. The client checks the
// exceptions (RegionNotKnown, InvalidExtents, InvalidRegionContext, ...); the gateway treats what it
// would have refused as a protocol violation. `bounds` lists each extent's ranges in the space's
// dimension order as lower, upper pairs (closed ranges): 2 * dimensions values per extent.
struct CreateRegion {
    HLACORE_TYPE(CreateRegion)
    std::uint32_t region = 0;
    std::uint32_t space = 0;
    Handles bounds;
    HLACORE_FIELDS(region, space, bounds)
};
// notifyAboutRegionModification: the region's new extents, used from the next message routed on.
struct ModifyRegion {
    HLACORE_TYPE(ModifyRegion)
    std::uint32_t region = 0;
    Handles bounds;
    HLACORE_FIELDS(region, bounds)
};
struct DeleteRegion {
    HLACORE_TYPE(DeleteRegion)
    std::uint32_t region = 0;
    HLACORE_FIELDS(region)
};
// Answered like RegisterObject (ObjectRegistered); attributes[i] is associated with regions[i] for this federate's updates
// before the instance is discovered by anyone.
struct RegisterObjectWithRegion {
    HLACORE_TYPE(RegisterObjectWithRegion)
    std::uint32_t request = 0;
    std::uint32_t object_class = 0;
    std::string name;
    Handles attributes;
    Handles regions;
    HLACORE_FIELDS(request, object_class, name, attributes, regions)
};
struct AssociateRegion {
    HLACORE_TYPE(AssociateRegion)
    std::uint32_t region = 0;
    std::uint32_t object = 0;
    Handles attributes;
    // IEEE 1516-2010: the region joins the attributes' update regions; HLA 1.3: it replaces them.
    bool adds = false;
    HLACORE_FIELDS(region, object, attributes, adds)
};
struct UnassociateRegion {
    HLACORE_TYPE(UnassociateRegion)
    std::uint32_t region = 0;
    std::uint32_t object = 0;
    Handles attributes;  // IEEE 1516-2010: these attributes; empty: all the object's (HLA 1.3)
    HLACORE_FIELDS(region, object, attributes)
};
struct SubscribeObjectClassWithRegion {
    HLACORE_TYPE(SubscribeObjectClassWithRegion)
    std::uint32_t object_class = 0;
    std::uint32_t region = 0;
    Handles attributes;
    bool active = true;
    HLACORE_FIELDS(object_class, region, attributes, active)
};
struct UnsubscribeObjectClassWithRegion {
    HLACORE_TYPE(UnsubscribeObjectClassWithRegion)
    std::uint32_t object_class = 0;
    std::uint32_t region = 0;
    HLACORE_FIELDS(object_class, region)
};
struct SubscribeInteractionClassWithRegion {
    HLACORE_TYPE(SubscribeInteractionClassWithRegion)
    std::uint32_t interaction_class = 0;
    std::uint32_t region = 0;
    bool active = true;
    HLACORE_FIELDS(interaction_class, region, active)
};
struct UnsubscribeInteractionClassWithRegion {
    HLACORE_TYPE(UnsubscribeInteractionClassWithRegion)
    std::uint32_t interaction_class = 0;
    std::uint32_t region = 0;
    HLACORE_FIELDS(interaction_class, region)
};
struct SendInteractionWithRegion {
    HLACORE_TYPE(SendInteractionWithRegion)
    std::uint32_t interaction_class = 0;
    HandleValues values;
    std::string tag;
    OptionalTime time;
    std::uint64_t serial = 0;
    Handles regions;  // one under HLA 1.3, any number under IEEE 1516-2010 (none: the default region)
    HLACORE_FIELDS(interaction_class, values, tag, time, serial, regions)
};
struct RequestClassUpdateWithRegion {
    HLACORE_TYPE(RequestClassUpdateWithRegion)
    std::uint32_t object_class = 0;
    Handles attributes;
    std::uint32_t region = 0;
    HLACORE_FIELDS(object_class, attributes, region)
};

// Gateway -> federate, while its attribute scope advisory switch is on (HLA 1.3 §6.13-6.14): attributes of
// a known object that came into scope (subscribed, through a region overlapping the owner's update region
// if by region, and owned by another federate) or left it.
struct AttributesInScope {
    HLACORE_TYPE(AttributesInScope)
    std::uint32_t object = 0;
    Handles attributes;
    HLACORE_FIELDS(object, attributes)
};
struct AttributesOutOfScope {
    HLACORE_TYPE(AttributesOutOfScope)
    std::uint32_t object = 0;
    Handles attributes;
    HLACORE_FIELDS(object, attributes)
};

// Gateway -> federate, while its attribute relevance advisory switch is on: owned attributes that some other
// federate now has in scope (turnUpdatesOnForObjectInstance), or that nobody has any more.
struct TurnUpdatesOn {
    HLACORE_TYPE(TurnUpdatesOn)
    std::uint32_t object = 0;
    Handles attributes;
    HLACORE_FIELDS(object, attributes)
};
struct TurnUpdatesOff {
    HLACORE_TYPE(TurnUpdatesOff)
    std::uint32_t object = 0;
    Handles attributes;
    HLACORE_FIELDS(object, attributes)
};

// ---- HLA 4's directed interactions (IEEE 1516.1-2025 §5.6-5.13, §6.14-6.15) ----
// An interaction sent to one object instance, received by the federates that subscribe to it for the instance's
// class or a superclass: those owning an attribute of the instance, or, subscribed universally, all that know it.

// Federate -> gateway: all the interaction classes the federate now publishes directed at instances of the
// object class (none: none any more).
struct PublishDirectedInteractions {
    HLACORE_TYPE(PublishDirectedInteractions)
    std::uint32_t object_class = 0;
    Handles interaction_classes;
    HLACORE_FIELDS(object_class, interaction_classes)
};
// Federate -> gateway: all the interaction classes the federate now receives directed at instances of the object
// class, when it owns an attribute of the instance (`owned`) or whenever it knows the instance (`universally`).
struct SubscribeDirectedInteractions {
    HLACORE_TYPE(SubscribeDirectedInteractions)
    std::uint32_t object_class = 0;
    Handles owned;
    Handles universally;
    HLACORE_FIELDS(object_class, owned, universally)
};
struct SendDirectedInteraction {
    HLACORE_TYPE(SendDirectedInteraction)
    std::uint32_t interaction_class = 0;
    std::uint32_t object = 0;
    HandleValues values;
    std::string tag;
    OptionalTime time;
    std::uint64_t serial = 0;
    HLACORE_FIELDS(interaction_class, object, values, tag, time, serial)
};
// Values: HandleValues, or HandleValueRefs for the gateway's forwarding: the same frame.
template <class Values>
struct BasicReceiveDirectedInteraction {
    HLACORE_TYPE(ReceiveDirectedInteraction)
    std::uint32_t interaction_class = 0;  // as the receiver subscribed to it
    std::uint32_t object = 0;
    Values values;
    std::string tag;
    std::uint8_t order = 1;
    std::uint8_t transport = 1;
    OptionalTime time;
    std::uint32_t sender = 0;
    std::uint64_t serial = 0;
    HLACORE_FIELDS(interaction_class, object, values, tag, order, transport, time, sender, serial)
};
using ReceiveDirectedInteraction = BasicReceiveDirectedInteraction<HandleValues>;
using ForwardedDirectedInteraction = BasicReceiveDirectedInteraction<HandleValueRefs>;

// Index in the variant == wire code.
#define HLACORE_X(name) , name
using Message = std::variant<std::monostate HLACORE_MESSAGES(HLACORE_X)>;
#undef HLACORE_X

// Each queued callback and filed answer takes this much: a large message keeps its fields on the heap
// (Boxed) rather than growing every one (144 bytes with libstdc++ on 64 bits, CreateFederation's).
static_assert(sizeof(Message) <= 144, "wire::Message grew: box the large message's fields");
}  // namespace hlacore::wire
