// CERTI 3.5.1's federate protocol, the messages a CERTI-built federate (its libRTI, JCERTI) and its `rtia`
// exchange (docs/certi.md): written from the protocol's published layouts, in our own code.
//
// A frame: one byte naming the byte order of every number in it (1: big endian, 0: little endian), the
// frame's whole length as a 32-bit number (these 5 bytes included), then the message: its type and an
// exception code (32-bit each); the exception's reason (a string) when the code is not 0, otherwise three
// optional fields, each a byte (1: present) and its value: a date (a double), a label and a tag (strings);
// then the fields of the message's type, in its layout's order. A string is a 32-bit length and its bytes; a
// list a 32-bit count and its items; a value a 32-bit length and its bytes; a bool one byte.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace hlacore::certi {

// The fields of the message bodies, each stored in one member of Message (below); unscoped in a namespace of
// their own, so that the layouts below name them bare.
namespace fields {
enum Field : std::uint8_t {
    VersionMajor, VersionMinor,      // u32
    FederationName, FedId,           // string
    FederateName, Name, Reason,      // string (Name: an object's, a class', an attribute's ... name)
    Federate, ObjectClass, InteractionClass, Object, Attribute, Parameter, Space, Dimension, Region,  // u32
    ResignAction,                    // u16
    Transport, Order,                // u8
    Flag,                            // bool: subscribe's active, DDM's passive, tick's multiple
    Lookahead, MinTick, MaxTick,     // double
    Handles,                         // list of u32: attributes, parameters, a synchronization set
    Values,                          // list of values, beside Handles
    OptionalName,                    // bool, then Name when true
    OptionalRetraction,              // bool, then Retraction when true
    Retraction,                      // u32 federate, u64 serial
    ExtentCount,                     // u32: CERTI 3.5.1 writes an extent set's size only, never its extents
    RtiVersion,                      // u8: 1 HLA 1.3, 2 IEEE 1516-2000, 3 IEEE 1516-2010
    FederateType,                    // string
    OptionalMim, OptionalTimeName,   // bool, then a string when true
};
}  // namespace fields
using fields::Field;

// The message types, in CERTI 3.5.1's numbering (from 1), each with its fields; then the two JCERTI adds.
#define HLACORE_CERTI_MESSAGES(X)                                                                           \
    X(OPEN_CONNEXION, VersionMajor, VersionMinor)                                                           \
    X(CLOSE_CONNEXION)                                                                                      \
    X(CREATE_FEDERATION_EXECUTION, FederationName, FedId)                                                   \
    X(DESTROY_FEDERATION_EXECUTION, FederationName)                                                         \
    X(JOIN_FEDERATION_EXECUTION, Federate, FederationName, FederateName)                                    \
    X(RESIGN_FEDERATION_EXECUTION, ResignAction)                                                            \
    X(REGISTER_FEDERATION_SYNCHRONIZATION_POINT, Handles)                                                   \
    X(SYNCHRONIZATION_POINT_REGISTRATION_FAILED)                                                            \
    X(SYNCHRONIZATION_POINT_REGISTRATION_SUCCEEDED)                                                         \
    X(ANNOUNCE_SYNCHRONIZATION_POINT)                                                                       \
    X(SYNCHRONIZATION_POINT_ACHIEVED)                                                                       \
    X(FEDERATION_SYNCHRONIZED)                                                                              \
    X(REQUEST_FEDERATION_SAVE)                                                                              \
    X(INITIATE_FEDERATE_SAVE)                                                                               \
    X(FEDERATE_SAVE_BEGUN)                                                                                  \
    X(FEDERATE_SAVE_COMPLETE)                                                                               \
    X(FEDERATE_SAVE_NOT_COMPLETE)                                                                           \
    X(FEDERATION_SAVED)                                                                                     \
    X(FEDERATION_NOT_SAVED)                                                                                 \
    X(REQUEST_FEDERATION_RESTORE)                                                                           \
    X(REQUEST_FEDERATION_RESTORE_FAILED, Reason)                                                            \
    X(REQUEST_FEDERATION_RESTORE_SUCCEEDED)                                                                 \
    X(INITIATE_FEDERATE_RESTORE, Federate)                                                                  \
    X(FEDERATE_RESTORE_COMPLETE)                                                                            \
    X(FEDERATE_RESTORE_NOT_COMPLETE)                                                                        \
    X(FEDERATION_RESTORED)                                                                                  \
    X(FEDERATION_NOT_RESTORED)                                                                              \
    X(FEDERATION_RESTORE_BEGUN)                                                                             \
    X(PUBLISH_OBJECT_CLASS, ObjectClass, Handles)                                                           \
    X(UNPUBLISH_OBJECT_CLASS, ObjectClass)                                                                  \
    X(PUBLISH_INTERACTION_CLASS, InteractionClass)                                                          \
    X(UNPUBLISH_INTERACTION_CLASS, InteractionClass)                                                        \
    X(SUBSCRIBE_OBJECT_CLASS_ATTRIBUTES, ObjectClass, Handles, Flag)                                        \
    X(UNSUBSCRIBE_OBJECT_CLASS, ObjectClass)                                                                \
    X(SUBSCRIBE_INTERACTION_CLASS, InteractionClass)                                                        \
    X(UNSUBSCRIBE_INTERACTION_CLASS, InteractionClass)                                                      \
    X(START_REGISTRATION_FOR_OBJECT_CLASS, ObjectClass)                                                     \
    X(STOP_REGISTRATION_FOR_OBJECT_CLASS, ObjectClass)                                                      \
    X(TURN_INTERACTIONS_ON, InteractionClass)                                                               \
    X(TURN_INTERACTIONS_OFF, InteractionClass)                                                              \
    X(REGISTER_OBJECT_INSTANCE, ObjectClass, Object, OptionalName)                                          \
    X(UPDATE_ATTRIBUTE_VALUES, ObjectClass, Object, Handles, Values, OptionalRetraction)                   \
    X(DISCOVER_OBJECT_INSTANCE, ObjectClass, Object, Name, OptionalRetraction)                             \
    X(REFLECT_ATTRIBUTE_VALUES, ObjectClass, Object, Handles, Values, OptionalRetraction)                  \
    X(SEND_INTERACTION, InteractionClass, Handles, Values, Region, OptionalRetraction)                     \
    X(RECEIVE_INTERACTION, InteractionClass, Handles, Values, Region, OptionalRetraction)                  \
    X(DELETE_OBJECT_INSTANCE, ObjectClass, Object, Name, OptionalRetraction)                               \
    X(LOCAL_DELETE_OBJECT_INSTANCE, Object)                                                                 \
    X(REMOVE_OBJECT_INSTANCE, ObjectClass, Object, Name, OptionalRetraction)                               \
    X(CHANGE_ATTRIBUTE_TRANSPORTATION_TYPE, Transport, Order, Object, Handles)                             \
    X(CHANGE_INTERACTION_TRANSPORTATION_TYPE, InteractionClass, Transport, Order)                          \
    X(REQUEST_OBJECT_ATTRIBUTE_VALUE_UPDATE, Object, Handles)                                              \
    X(REQUEST_CLASS_ATTRIBUTE_VALUE_UPDATE, ObjectClass, Handles)                                          \
    X(PROVIDE_ATTRIBUTE_VALUE_UPDATE, Object, Handles)                                                     \
    X(ATTRIBUTES_IN_SCOPE, Object, Handles)                                                                \
    X(ATTRIBUTES_OUT_OF_SCOPE, Object, Handles)                                                            \
    X(TURN_UPDATES_ON_FOR_OBJECT_INSTANCE, Object, Handles)                                                \
    X(TURN_UPDATES_OFF_FOR_OBJECT_INSTANCE, Object, Handles)                                               \
    X(REQUEST_ATTRIBUTE_OWNERSHIP_DIVESTITURE)                                                             \
    X(REQUEST_ATTRIBUTE_OWNERSHIP_ASSUMPTION, Object, Handles)                                             \
    X(NEGOTIATED_ATTRIBUTE_OWNERSHIP_DIVESTITURE, Object, Handles)                                         \
    X(ATTRIBUTE_OWNERSHIP_DIVESTITURE_NOTIFICATION, Object, Handles)                                       \
    X(ATTRIBUTE_OWNERSHIP_ACQUISITION_NOTIFICATION, Object, Handles)                                       \
    X(REQUEST_ATTRIBUTE_OWNERSHIP_ACQUISITION, Object, Handles)                                            \
    X(REQUEST_ATTRIBUTE_OWNERSHIP_RELEASE, Object, Handles)                                                \
    X(QUERY_ATTRIBUTE_OWNERSHIP, Object, Attribute)                                                        \
    X(INFORM_ATTRIBUTE_OWNERSHIP, Object, Attribute, Federate)                                             \
    X(IS_ATTRIBUTE_OWNED_BY_FEDERATE, Object, Attribute)                                                   \
    X(ATTRIBUTE_IS_NOT_OWNED, Object, Attribute, Federate)                                                 \
    X(ATTRIBUTE_OWNED_BY_RTI)                                                                              \
    X(ATTRIBUTE_OWNERSHIP_ACQUISITION_IF_AVAILABLE, Object, Handles)                                       \
    X(ATTRIBUTE_OWNERSHIP_UNAVAILABLE, Object, Handles)                                                    \
    X(UNCONDITIONAL_ATTRIBUTE_OWNERSHIP_DIVESTITURE, Object, Handles)                                      \
    X(ATTRIBUTE_OWNERSHIP_ACQUISITION, Object, Handles)                                                    \
    X(CANCEL_NEGOTIATED_ATTRIBUTE_OWNERSHIP_DIVESTITURE, Object, Handles)                                  \
    X(ATTRIBUTE_OWNERSHIP_RELEASE_RESPONSE, Object, Handles)                                               \
    X(CANCEL_ATTRIBUTE_OWNERSHIP_ACQUISITION, Object, Handles)                                             \
    X(CONFIRM_ATTRIBUTE_OWNERSHIP_ACQUISITION_CANCELLATION, Object, Handles)                               \
    X(CHANGE_ATTRIBUTE_ORDER_TYPE, Transport, Order, Object, Handles)                                      \
    X(CHANGE_INTERACTION_ORDER_TYPE, InteractionClass, Transport, Order)                                   \
    X(ENABLE_TIME_REGULATION, Lookahead)                                                                   \
    X(DISABLE_TIME_REGULATION, Lookahead)                                                                  \
    X(ENABLE_TIME_CONSTRAINED)                                                                             \
    X(DISABLE_TIME_CONSTRAINED)                                                                            \
    X(QUERY_LBTS)                                                                                          \
    X(QUERY_FEDERATE_TIME)                                                                                 \
    X(QUERY_MIN_NEXT_EVENT_TIME)                                                                           \
    X(MODIFY_LOOKAHEAD, Lookahead)                                                                         \
    X(QUERY_LOOKAHEAD, Lookahead)                                                                          \
    X(RETRACT, Retraction)                                                                                 \
    X(REQUEST_RETRACTION)                                                                                  \
    X(TIME_ADVANCE_REQUEST)                                                                                \
    X(TIME_ADVANCE_REQUEST_AVAILABLE)                                                                      \
    X(NEXT_EVENT_REQUEST)                                                                                  \
    X(NEXT_EVENT_REQUEST_AVAILABLE)                                                                        \
    X(FLUSH_QUEUE_REQUEST)                                                                                 \
    X(TIME_ADVANCE_GRANT)                                                                                  \
    X(ENABLE_ASYNCHRONOUS_DELIVERY)                                                                        \
    X(DISABLE_ASYNCHRONOUS_DELIVERY)                                                                       \
    X(TIME_REGULATION_ENABLED)                                                                             \
    X(TIME_CONSTRAINED_ENABLED)                                                                            \
    X(DDM_CREATE_REGION, Space, ExtentCount, Region)                                                       \
    X(DDM_MODIFY_REGION, Region, ExtentCount)                                                              \
    X(DDM_DELETE_REGION, Region)                                                                           \
    X(DDM_REGISTER_OBJECT, ObjectClass, Object, OptionalName, Handles)                                     \
    X(DDM_ASSOCIATE_REGION, Object, Region, Handles)                                                       \
    X(DDM_UNASSOCIATE_REGION, Object, Region)                                                              \
    X(DDM_SUBSCRIBE_ATTRIBUTES, ObjectClass, Region, Flag, Handles)                                        \
    X(DDM_UNSUBSCRIBE_ATTRIBUTES, ObjectClass, Region)                                                     \
    X(DDM_SUBSCRIBE_INTERACTION, InteractionClass, Region, Flag)                                           \
    X(DDM_UNSUBSCRIBE_INTERACTION, InteractionClass, Region, Flag)                                         \
    X(DDM_REQUEST_UPDATE, ObjectClass, Region, Handles)                                                    \
    X(GET_OBJECT_CLASS_HANDLE, ObjectClass, Name)                                                          \
    X(GET_OBJECT_CLASS_NAME, ObjectClass, Name)                                                            \
    X(GET_ATTRIBUTE_HANDLE, ObjectClass, Name, Attribute)                                                  \
    X(GET_ATTRIBUTE_NAME, ObjectClass, Name, Attribute)                                                    \
    X(GET_INTERACTION_CLASS_HANDLE, InteractionClass, Name)                                                \
    X(GET_INTERACTION_CLASS_NAME, InteractionClass, Name)                                                  \
    X(GET_PARAMETER_HANDLE, InteractionClass, Name, Parameter)                                             \
    X(GET_PARAMETER_NAME, InteractionClass, Name, Parameter)                                               \
    X(GET_OBJECT_INSTANCE_HANDLE, Object, Name)                                                            \
    X(GET_OBJECT_INSTANCE_NAME, Object, Name)                                                              \
    X(GET_SPACE_HANDLE, Name, Space)                                                                       \
    X(GET_SPACE_NAME, Name, Space)                                                                         \
    X(GET_DIMENSION_HANDLE, Name, Space, Dimension)                                                        \
    X(GET_DIMENSION_NAME, Name, Space, Dimension)                                                          \
    X(GET_ATTRIBUTE_SPACE_HANDLE, ObjectClass, Attribute, Space)                                           \
    X(GET_OBJECT_CLASS, ObjectClass, Object)                                                               \
    X(GET_INTERACTION_SPACE_HANDLE, InteractionClass, Space)                                               \
    X(GET_TRANSPORTATION_HANDLE, Name, Transport)                                                          \
    X(GET_TRANSPORTATION_NAME, Name, Transport)                                                            \
    X(GET_ORDERING_HANDLE, Name, Order)                                                                    \
    X(GET_ORDERING_NAME, Name, Order)                                                                      \
    X(ENABLE_CLASS_RELEVANCE_ADVISORY_SWITCH)                                                              \
    X(DISABLE_CLASS_RELEVANCE_ADVISORY_SWITCH)                                                             \
    X(ENABLE_ATTRIBUTE_RELEVANCE_ADVISORY_SWITCH)                                                          \
    X(DISABLE_ATTRIBUTE_RELEVANCE_ADVISORY_SWITCH)                                                         \
    X(ENABLE_ATTRIBUTE_SCOPE_ADVISORY_SWITCH)                                                              \
    X(DISABLE_ATTRIBUTE_SCOPE_ADVISORY_SWITCH)                                                             \
    X(ENABLE_INTERACTION_RELEVANCE_ADVISORY_SWITCH)                                                        \
    X(DISABLE_INTERACTION_RELEVANCE_ADVISORY_SWITCH)                                                       \
    X(TICK_REQUEST, Flag, MinTick, MaxTick)                                                                \
    X(TICK_REQUEST_NEXT)                                                                                   \
    X(TICK_REQUEST_STOP)                                                                                   \
    X(RESERVE_OBJECT_INSTANCE_NAME, Name)                                                                  \
    X(RESERVE_OBJECT_INSTANCE_NAME_SUCCEEDED, Name)                                                        \
    X(RESERVE_OBJECT_INSTANCE_NAME_FAILED, Name)                                                          \
    /* JCERTI's IEEE 1516-2010 ambassador: create and join with FOM modules (Values: their paths) */         \
    X(CREATE_FEDERATION_EXECUTION_V4, FederationName, RtiVersion, Values, OptionalMim, OptionalTimeName)   \
    X(JOIN_FEDERATION_EXECUTION_V4, Federate, OptionalName, FederateType, RtiVersion, FederationName, Values)

#define HLACORE_CERTI_TYPE(name, ...) name,
enum class Type : std::int32_t { NOT_USED = 0, HLACORE_CERTI_MESSAGES(HLACORE_CERTI_TYPE) LAST };
#undef HLACORE_CERTI_TYPE

// CERTI's exception codes (TypeException), in its numbering from 1 (0: none). Its names are HLA 1.3's where
// HLA 1.3 has the exception; the others are CERTI's own.
#define HLACORE_CERTI_EXCEPTIONS(X)                                                                         \
    X(ArrayIndexOutOfBounds) X(AsynchronousDeliveryAlreadyEnabled) X(AsynchronousDeliveryAlreadyDisabled)   \
    X(AttributeAlreadyOwned) X(AttributeAlreadyBeingAcquired) X(AttributeAlreadyBeingDivested)              \
    X(AttributeAcquisitionWasNotRequested) X(AttributeDivestitureWasNotRequested) X(AttributeNotDefined)    \
    X(AttributeNotKnown) X(AttributeNotOwned) X(AttributeNotPublished) X(AttributeNotSubscribed)            \
    X(ConcurrentAccessAttempted) X(CouldNotDiscover) X(CouldNotOpenRID) X(CouldNotOpenFED)                  \
    X(CouldNotRestore) X(DeletePrivilegeNotHeld) X(ErrorReadingRID) X(ErrorReadingFED) X(EventNotKnown)     \
    X(FederateAlreadyPaused) X(FederateAlreadyExecutionMember) X(FederateDoesNotExist)                      \
    X(FederateInternalError) X(FederateNameAlreadyInUse) X(FederateNotExecutionMember)                      \
    X(FederateNotPaused) X(FederateNotPublishing) X(FederateNotSubscribing) X(FederateOwnsAttributes)       \
    X(FederatesCurrentlyJoined) X(FederateWasNotAskedToReleaseAttribute) X(FederationAlreadyPaused)         \
    X(FederationExecutionAlreadyExists) X(FederationExecutionDoesNotExist) X(FederationNotPaused)           \
    X(FederationTimeAlreadyPassed) X(RegionNotKnown) X(IDsupplyExhausted) X(InteractionClassNotDefined)     \
    X(InteractionClassNotKnown) X(InteractionClassNotPublished) X(InteractionParameterNotDefined)           \
    X(InteractionParameterNotKnown) X(InvalidDivestitureCondition) X(InvalidExtents)                        \
    X(InvalidFederationTime) X(InvalidFederationTimeDelta) X(InvalidObjectHandle) X(InvalidResignAction)    \
    X(InvalidRetractionHandle) X(InvalidRoutingSpace) X(MemoryExhausted) X(NameNotFound)                    \
    X(NoPauseRequested) X(NoResumeRequested) X(ObjectClassNotDefined) X(ObjectClassNotKnown)                \
    X(ObjectClassNotPublished) X(ObjectClassNotSubscribed) X(ObjectNotKnown) X(ObjectAlreadyRegistered)     \
    X(RestoreInProgress) X(RestoreNotRequested) X(RTICannotRestore) X(RTIinternalError)                     \
    X(SpaceNotDefined) X(SaveInProgress) X(SaveNotInitiated) X(SecurityError) X(SocketNotConnected)         \
    X(MessageNotSent) X(MessageNotReceived) X(SocketNotClosed) X(RingBufferNotCreated)                      \
    X(RingBufferNotClosed) X(RingBufferNotDeleted) X(RingBufferNotAttached) X(MessageTooLong)               \
    X(BufferFull) X(BufferEmpty) X(SocketSHMNotCreated) X(SocketSHMNotOpen) X(SocketSHMNotDeleted)          \
    X(SpecifiedSaveLabelDoesNotExist) X(TimeAdvanceAlreadyInProgress) X(TimeAdvanceWasNotInProgress)        \
    X(TooManyIDsRequested) X(UnableToPerformSave) X(UnimplementedService) X(UnknownLabel)                   \
    X(ValueCountExceeded) X(ValueLengthExceeded) X(AttributeAcquisitionWasNotCanceled)                      \
    X(DimensionNotDefined) X(EnableTimeConstrainedPending) X(EnableTimeConstrainedWasNotPending)            \
    X(EnableTimeRegulationPending) X(EnableTimeRegulationWasNotPending) X(FederateLoggingServiceCalls)      \
    X(HandleValuePairMaximumExceeded) X(InteractionClassNotSubscribed) X(InvalidHandleValuePairSetContext)  \
    X(InvalidLookahead) X(InvalidOrderingHandle) X(InvalidRegionContext) X(InvalidTransportationHandle)     \
    X(OwnershipAcquisitionPending) X(RegionInUse) X(SynchronizationPointLabelWasNotAnnounced)               \
    X(TimeConstrainedAlreadyEnabled) X(TimeConstrainedWasNotEnabled) X(TimeRegulationAlreadyEnabled)        \
    X(TimeRegulationWasNotEnabled) X(NetworkError) X(NetworkSignal) X(IllegalName)

#define HLACORE_CERTI_EXCEPTION(name) name,
enum class Exception : std::int32_t { None = 0, HLACORE_CERTI_EXCEPTIONS(HLACORE_CERTI_EXCEPTION) Count };
#undef HLACORE_CERTI_EXCEPTION

// The protocol version the opening handshake agrees on (CERTI 3.5.1's is 1.0).
constexpr std::uint32_t kVersionMajor = 1;
constexpr std::uint32_t kVersionMinor = 0;
// The 5 bytes before the message: the byte order and the frame's length.
constexpr std::size_t kFrameHeader = 5;
// A frame longer than this is refused before it is read: CERTI's own limit is the 32-bit length.
constexpr std::uint32_t kMaxFrame = 256u << 20;

struct EventRetraction {
    std::uint32_t federate = 0;
    std::uint64_t serial = 0;
};

// One message: the common part, and every body field any type has (each type reads and writes its own).
struct Message {
    Type type = Type::NOT_USED;
    Exception exception = Exception::None;
    std::string reason;  // with an exception
    std::optional<double> date;
    std::optional<std::string> label, tag;

    std::uint32_t version_major = 0, version_minor = 0;
    std::string federation_name, fed_id, federate_name, name, restore_reason, federate_type;
    std::uint8_t rti_version = 0;
    std::optional<std::string> mim, time_name;
    std::uint32_t federate = 0, object_class = 0, interaction_class = 0, object = 0, attribute = 0, parameter = 0,
                  space = 0, dimension = 0, region = 0, extent_count = 0;
    std::uint16_t resign_action = 0;
    std::uint8_t transport = 0, order = 0;
    bool flag = false;
    bool has_name = false;  // OptionalName
    double lookahead = 0, min_tick = 0, max_tick = 0;
    std::vector<std::uint32_t> handles;
    std::vector<std::string> values;
    std::optional<EventRetraction> retraction;

    Message() = default;
    explicit Message(Type t) : type(t) {}
};

// A frame that cannot be a message of the protocol (its text says where and why).
class ProtocolError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

const char* type_name(Type type);            // "TICK_REQUEST"; "type 200" is not one
const char* exception_name(Exception code);  // "RTIinternalError"; "" for None
// The CERTI exception of an HLA 1.3 exception's name, RTIinternalError for a name CERTI does not have.
Exception exception_named(std::string_view name);

// The frame of `m`, numbers in big-endian order when `big_endian`, else little-endian.
std::string encode(const Message& m, bool big_endian);
// The length a frame says it has, from its first kFrameHeader bytes (ProtocolError: a bad byte-order flag,
// a length shorter than the header or above kMaxFrame).
std::uint32_t frame_length(std::string_view header);
// The message of a whole frame (ProtocolError: an unknown type, a truncated field); bytes after the last
// field are ignored, as CERTI does.
// `big_endian` is set to the frame's byte order, which the answer keeps.
Message decode(std::string_view frame, bool* big_endian = nullptr);

}  // namespace hlacore::certi
