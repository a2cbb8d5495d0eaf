// The HLA 1.3 C++ interface of hlacore (libRTI-NG): the class RTI holding the basic types, the exceptions,
// the handle and value sets, RTIambassador (the services) and FederateAmbassador (the callbacks), with the
// names and signatures of the HLA 1.3 specification, so that a federate written for another HLA 1.3 RTI
// builds against this one by changing only its include and library paths (docs/cpp-api.md).
//
// Where the other RTIs' headers differ, this one accepts both spellings:
// - no exception specifications, so that overriding callbacks may declare `throw (...)` (CERTI's style,
//   before C++17) or nothing (OpenRTI's under C++17);
// - RTI_USES_STD_FSTREAM may be defined or not: the standard streams are used either way;
// - ULong is unsigned long and Long long, as in CERTI and the DMSO headers; a value's length may also be
//   taken into an unsigned int, OpenRTI's ULong;
// - Exception has both the fields everyone has and CERTI's cloneSelf/throwSelf/displayMe;
// - OpenRTI's RTI_UNIQUE_PTR, RTI_NOEXCEPT and RTI_THROW are defined.
#ifndef HLACORE_RTI_HH
#define HLACORE_RTI_HH

#include <fstream>  // CERTI's RTI.hh includes it: federates may rely on it
#include <memory>
#include <string>

#define RTI_EXPORT __attribute__((visibility("default")))
#define FEDTIME_EXPORT __attribute__((visibility("default")))
#define RTI_STD std
// For code written with OpenRTI's macros: exception specifications, and the owning pointer of its examples.
#define RTI_NOEXCEPT noexcept
#define RTI_THROW(list)
#define RTI_UNIQUE_PTR std::unique_ptr

class RTIambPrivateRefs;
struct RTIambPrivateData;

class RTI_EXPORT RTI {
public:
    // ---- basic types ----
    typedef unsigned short UShort;
    typedef short Short;
    typedef unsigned long ULong;
    typedef long Long;
    typedef double Double;
    typedef float Float;

    enum Boolean { RTI_FALSE = 0, RTI_TRUE };

    // The base of every exception an HLA 1.3 service throws; _reason is a copy owned by the exception.
    class RTI_EXPORT Exception {
    public:
        ULong _serial;
        char* _reason;
        const char* _name;
        Exception(const char* reason);
        Exception(ULong serial, const char* reason);
        Exception(const Exception& toCopy);
        virtual ~Exception();
        Exception& operator=(const Exception& toCopy);
        virtual Exception* cloneSelf() const noexcept = 0;
        virtual void throwSelf() const = 0;
        // "Name: reason".
        const std::string displayMe() const;
    };

#define RTI_EXCEPT(A)                                                                          \
    class RTI_EXPORT A : public Exception {                                                    \
    public:                                                                                    \
        A(const char* reason) : Exception(reason) { _name = #A; }                             \
        A(ULong serial, const char* reason = 0) : Exception(serial, reason) { _name = #A; }   \
        A(const A& toCopy) : Exception(toCopy) { _name = #A; }                                \
        Exception* cloneSelf() const noexcept override { return new A(*this); }               \
        void throwSelf() const override { throw *this; }                                      \
    };

    RTI_EXCEPT(ArrayIndexOutOfBounds)
    RTI_EXCEPT(AsynchronousDeliveryAlreadyDisabled)
    RTI_EXCEPT(AsynchronousDeliveryAlreadyEnabled)
    RTI_EXCEPT(AttributeAcquisitionWasNotRequested)
    RTI_EXCEPT(AttributeAcquisitionWasNotCanceled)
    RTI_EXCEPT(AttributeAlreadyBeingAcquired)
    RTI_EXCEPT(AttributeAlreadyBeingDivested)
    RTI_EXCEPT(AttributeAlreadyOwned)
    RTI_EXCEPT(AttributeDivestitureWasNotRequested)
    RTI_EXCEPT(AttributeNotDefined)
    RTI_EXCEPT(AttributeNotKnown)
    RTI_EXCEPT(AttributeNotOwned)
    RTI_EXCEPT(AttributeNotPublished)
    RTI_EXCEPT(ConcurrentAccessAttempted)
    RTI_EXCEPT(CouldNotDiscover)
    RTI_EXCEPT(CouldNotOpenFED)
    RTI_EXCEPT(CouldNotRestore)
    RTI_EXCEPT(DeletePrivilegeNotHeld)
    RTI_EXCEPT(DimensionNotDefined)
    RTI_EXCEPT(EnableTimeConstrainedPending)
    RTI_EXCEPT(EnableTimeConstrainedWasNotPending)
    RTI_EXCEPT(EnableTimeRegulationPending)
    RTI_EXCEPT(EnableTimeRegulationWasNotPending)
    RTI_EXCEPT(ErrorReadingFED)
    RTI_EXCEPT(EventNotKnown)
    RTI_EXCEPT(FederateAlreadyExecutionMember)
    RTI_EXCEPT(FederateInternalError)
    RTI_EXCEPT(FederateLoggingServiceCalls)
    RTI_EXCEPT(FederateNotExecutionMember)
    RTI_EXCEPT(FederateOwnsAttributes)
    RTI_EXCEPT(FederateWasNotAskedToReleaseAttribute)
    RTI_EXCEPT(FederatesCurrentlyJoined)
    RTI_EXCEPT(FederationExecutionAlreadyExists)
    RTI_EXCEPT(FederationExecutionDoesNotExist)
    RTI_EXCEPT(FederationTimeAlreadyPassed)
    RTI_EXCEPT(HandleValuePairMaximumExceeded)
    RTI_EXCEPT(InteractionClassNotDefined)
    RTI_EXCEPT(InteractionClassNotKnown)
    RTI_EXCEPT(InteractionClassNotPublished)
    RTI_EXCEPT(InteractionClassNotSubscribed)
    RTI_EXCEPT(InteractionParameterNotDefined)
    RTI_EXCEPT(InteractionParameterNotKnown)
    RTI_EXCEPT(InvalidExtents)
    RTI_EXCEPT(InvalidFederationTime)
    RTI_EXCEPT(InvalidHandleValuePairSetContext)
    RTI_EXCEPT(InvalidLookahead)
    RTI_EXCEPT(InvalidOrderingHandle)
    RTI_EXCEPT(InvalidRegionContext)
    RTI_EXCEPT(InvalidResignAction)
    RTI_EXCEPT(InvalidRetractionHandle)
    RTI_EXCEPT(InvalidTransportationHandle)
    RTI_EXCEPT(MemoryExhausted)
    RTI_EXCEPT(NameNotFound)
    RTI_EXCEPT(ObjectClassNotDefined)
    RTI_EXCEPT(ObjectClassNotKnown)
    RTI_EXCEPT(ObjectClassNotPublished)
    RTI_EXCEPT(ObjectClassNotSubscribed)
    RTI_EXCEPT(ObjectNotKnown)
    RTI_EXCEPT(ObjectAlreadyRegistered)
    RTI_EXCEPT(OwnershipAcquisitionPending)
    RTI_EXCEPT(RegionInUse)
    RTI_EXCEPT(RegionNotKnown)
    RTI_EXCEPT(RestoreInProgress)
    RTI_EXCEPT(RestoreNotRequested)
    RTI_EXCEPT(RTIinternalError)
    RTI_EXCEPT(SpaceNotDefined)
    RTI_EXCEPT(SaveInProgress)
    RTI_EXCEPT(SaveNotInitiated)
    RTI_EXCEPT(SpecifiedSaveLabelDoesNotExist)
    RTI_EXCEPT(SynchronizationPointLabelWasNotAnnounced)
    RTI_EXCEPT(TimeAdvanceAlreadyInProgress)
    RTI_EXCEPT(TimeAdvanceWasNotInProgress)
    RTI_EXCEPT(TimeConstrainedAlreadyEnabled)
    RTI_EXCEPT(TimeConstrainedWasNotEnabled)
    RTI_EXCEPT(TimeRegulationAlreadyEnabled)
    RTI_EXCEPT(TimeRegulationWasNotEnabled)
    RTI_EXCEPT(UnableToPerformSave)
    RTI_EXCEPT(ValueCountExceeded)
    RTI_EXCEPT(ValueLengthExceeded)

    // ---- handles ----
    enum ResignAction { RELEASE_ATTRIBUTES = 1, DELETE_OBJECTS, DELETE_OBJECTS_AND_RELEASE_ATTRIBUTES, NO_ACTION };

    class Region;
    class FederateAmbassador;
    typedef FederateAmbassador* FederateAmbassadorPtr;
    typedef Long SpaceHandle;
    typedef ULong ObjectClassHandle;
    typedef ULong InteractionClassHandle;
    typedef ULong ExtentIndex;
    typedef ULong Handle;
    typedef Handle AttributeHandle;
    typedef Handle ParameterHandle;
    typedef Handle ObjectHandle;
    typedef Handle DimensionHandle;
    typedef ULong FederateHandle;
    typedef Handle TransportationHandle;
    typedef TransportationHandle TransportType;
    typedef Handle OrderingHandle;
    typedef OrderingHandle OrderType;
    typedef ULong FederateID;
    typedef ULong UniqueID;
    typedef Double TickTime;
    typedef ULong RegionToken;

    // ---- sets (made by their factories; the caller deletes them) ----
    // Indexes run from start() while valid(), by next(): 0, 1, ... size()-1 here.
    class RTI_EXPORT AttributeHandleValuePairSet {
    public:
        virtual ~AttributeHandleValuePairSet() {}
        virtual ULong size() const = 0;
        virtual Handle getHandle(ULong index) const = 0;
        virtual ULong getValueLength(ULong index) const = 0;
        // Copies the value into buffer (getValueLength bytes) and sets length.
        virtual void getValue(ULong index, char* buffer, ULong& length) const = 0;
        // The value in place, valid as long as the set is; sets length.
        virtual char* getValuePointer(ULong index, ULong& length) const = 0;
        // The same with an unsigned int length, as code written for OpenRTI's headers (ULong = unsigned int) has it.
        void getValue(ULong index, char* buffer, unsigned int& length) const {
            ULong n = 0;
            getValue(index, buffer, n);
            length = static_cast<unsigned int>(n);
        }
        char* getValuePointer(ULong index, unsigned int& length) const {
            ULong n = 0;
            char* value = getValuePointer(index, n);
            length = static_cast<unsigned int>(n);
            return value;
        }
        // In reflectAttributeValues: how the value came (InvalidHandleValuePairSetContext elsewhere).
        virtual TransportType getTransportType(ULong index) const = 0;
        virtual OrderType getOrderType(ULong index) const = 0;
        virtual Region* getRegion(ULong index) const = 0;
        // Adds the pair, or replaces the value of a handle already in the set.
        virtual void add(Handle handle, const char* value, ULong length) = 0;
        virtual void remove(Handle handle) = 0;  // ArrayIndexOutOfBounds when absent
        // Adds other's pair at index, then advances index.
        virtual void moveFrom(const AttributeHandleValuePairSet& other, ULong& index) = 0;
        virtual void empty() = 0;
        virtual ULong start() const = 0;
        virtual ULong valid(ULong index) const = 0;
        virtual ULong next(ULong index) const = 0;
    };
    class RTI_EXPORT AttributeSetFactory {
    public:
        static AttributeHandleValuePairSet* create(ULong count);
    };

    class RTI_EXPORT AttributeHandleSet {
    public:
        virtual ~AttributeHandleSet() {}
        virtual ULong size() const = 0;
        virtual AttributeHandle getHandle(ULong index) const = 0;
        virtual void add(AttributeHandle handle) = 0;  // once: adding a member again changes nothing
        virtual void remove(AttributeHandle handle) = 0;
        virtual void empty() = 0;
        virtual Boolean isEmpty() const = 0;
        virtual Boolean isMember(AttributeHandle handle) const = 0;
    };
    class RTI_EXPORT AttributeHandleSetFactory {
    public:
        static AttributeHandleSet* create(ULong count);
    };

    class RTI_EXPORT FederateHandleSet {
    public:
        virtual ~FederateHandleSet() {}
        virtual ULong size() const = 0;
        virtual FederateHandle getHandle(ULong index) const = 0;
        virtual void add(FederateHandle handle) = 0;
        virtual void remove(FederateHandle handle) = 0;
        virtual void empty() = 0;
        virtual Boolean isMember(FederateHandle handle) const = 0;
    };
    class RTI_EXPORT FederateHandleSetFactory {
    public:
        static FederateHandleSet* create(ULong count);
    };

    class RTI_EXPORT ParameterHandleValuePairSet {
    public:
        virtual ~ParameterHandleValuePairSet() {}
        virtual ULong size() const = 0;
        virtual Handle getHandle(ULong index) const = 0;
        virtual ULong getValueLength(ULong index) const = 0;
        virtual void getValue(ULong index, char* buffer, ULong& length) const = 0;
        virtual char* getValuePointer(ULong index, ULong& length) const = 0;
        void getValue(ULong index, char* buffer, unsigned int& length) const {  // OpenRTI's ULong, as above
            ULong n = 0;
            getValue(index, buffer, n);
            length = static_cast<unsigned int>(n);
        }
        char* getValuePointer(ULong index, unsigned int& length) const {
            ULong n = 0;
            char* value = getValuePointer(index, n);
            length = static_cast<unsigned int>(n);
            return value;
        }
        virtual TransportType getTransportType() const = 0;
        virtual OrderType getOrderType() const = 0;
        virtual Region* getRegion() const = 0;
        virtual void add(Handle handle, const char* value, ULong length) = 0;
        virtual void remove(Handle handle) = 0;
        virtual void moveFrom(const ParameterHandleValuePairSet& other, ULong& index) = 0;
        virtual void empty() = 0;
        virtual ULong start() const = 0;
        virtual ULong valid(ULong index) const = 0;
        virtual ULong next(ULong index) const = 0;
    };
    class RTI_EXPORT ParameterSetFactory {
    public:
        static ParameterHandleValuePairSet* create(ULong count);
    };

    // A region of a routing space (HLA 1.3 §9), made by RTIambassador::createRegion. Bounds set here take
    // effect at notifyAboutRegionModification.
    class RTI_EXPORT Region {
    public:
        virtual ~Region() {}
        virtual ULong getRangeLowerBound(ExtentIndex extent, DimensionHandle dimension) const = 0;
        virtual ULong getRangeUpperBound(ExtentIndex extent, DimensionHandle dimension) const = 0;
        virtual void setRangeLowerBound(ExtentIndex extent, DimensionHandle dimension, ULong bound) = 0;
        virtual void setRangeUpperBound(ExtentIndex extent, DimensionHandle dimension, ULong bound) = 0;
        virtual SpaceHandle getSpaceHandle() const noexcept = 0;
        virtual ULong getNumberOfExtents() const noexcept = 0;
        virtual ULong getRangeLowerBoundNotificationLimit(ExtentIndex extent, DimensionHandle dimension) const = 0;
        virtual ULong getRangeUpperBoundNotificationLimit(ExtentIndex extent, DimensionHandle dimension) const = 0;
    };

    // ---- logical time (RTIfedTime in fedtime.hh, libFedTime) ----
    class FEDTIME_EXPORT FedTime {
    public:
        virtual ~FedTime() {}
        virtual void setZero() = 0;
        virtual Boolean isZero() = 0;
        virtual void setEpsilon() = 0;
        virtual void setPositiveInfinity() = 0;
        virtual Boolean isPositiveInfinity() = 0;
        virtual FedTime& operator+=(const FedTime&) = 0;
        virtual FedTime& operator-=(const FedTime&) = 0;
        virtual Boolean operator<=(const FedTime&) const = 0;
        virtual Boolean operator<(const FedTime&) const = 0;
        virtual Boolean operator>=(const FedTime&) const = 0;
        virtual Boolean operator>(const FedTime&) const = 0;
        virtual Boolean operator==(const FedTime&) const = 0;
        virtual FedTime& operator=(const FedTime&) = 0;
        virtual int encodedLength() const = 0;
        virtual void encode(char* buffer) const = 0;
        virtual int getPrintableLength() const = 0;
        virtual void getPrintableString(char* buffer) = 0;
    };
    class FEDTIME_EXPORT FedTimeFactory {
    public:
        static FedTime* makeZero();
        static FedTime* decode(const char* buffer);
    };

    struct EventRetractionHandle_s {
        UniqueID theSerialNumber;
        FederateHandle sendingFederate;
    };
    typedef struct EventRetractionHandle_s EventRetractionHandle;

    // ---- the services (HLA 1.3 §4-10); each throws the exceptions the specification lists for it ----
    class RTI_EXPORT RTIambassador {
    public:
        typedef FederateAmbassador* FederateAmbassadorPtr;

        // Connects to the gateway named by $HLACORE_RTIG (HOST:PORT, or unix:PATH), else CERTI's $CERTI_HOST and
        // $CERTI_TCP_PORT, else 127.0.0.1:60400; RTIinternalError naming the address when nothing answers.
        RTIambassador();
        ~RTIambassador();
        RTIambassador(const RTIambassador&) = delete;
        RTIambassador& operator=(const RTIambassador&) = delete;

        // Federation management (§4)
        void createFederationExecution(const char* executionName, const char* FED);
        void destroyFederationExecution(const char* executionName);
        FederateHandle joinFederationExecution(const char* yourName, const char* executionName,
                                               FederateAmbassadorPtr federateAmbassador);
        void resignFederationExecution(ResignAction theAction);
        void registerFederationSynchronizationPoint(const char* label, const char* tag);
        void registerFederationSynchronizationPoint(const char* label, const char* tag,
                                                    const FederateHandleSet& synchronizationSet);
        void synchronizationPointAchieved(const char* label);
        void requestFederationSave(const char* label, const FedTime& theTime);
        void requestFederationSave(const char* label);
        void federateSaveBegun();
        void federateSaveComplete();
        void federateSaveNotComplete();
        void requestFederationRestore(const char* label);
        void federateRestoreComplete();
        void federateRestoreNotComplete();

        // Declaration management (§5)
        void publishObjectClass(ObjectClassHandle theClass, const AttributeHandleSet& attributeList);
        void unpublishObjectClass(ObjectClassHandle theClass);
        void publishInteractionClass(InteractionClassHandle theInteraction);
        void unpublishInteractionClass(InteractionClassHandle theInteraction);
        void subscribeObjectClassAttributes(ObjectClassHandle theClass, const AttributeHandleSet& attributeList,
                                            Boolean active = RTI_TRUE);
        void unsubscribeObjectClass(ObjectClassHandle theClass);
        void subscribeInteractionClass(InteractionClassHandle theClass, Boolean active = RTI_TRUE);
        void unsubscribeInteractionClass(InteractionClassHandle theClass);

        // Object management (§6)
        ObjectHandle registerObjectInstance(ObjectClassHandle theClass, const char* theObject);
        ObjectHandle registerObjectInstance(ObjectClassHandle theClass);
        EventRetractionHandle updateAttributeValues(ObjectHandle theObject,
                                                    const AttributeHandleValuePairSet& theAttributes,
                                                    const FedTime& theTime, const char* theTag);
        void updateAttributeValues(ObjectHandle theObject, const AttributeHandleValuePairSet& theAttributes,
                                   const char* theTag);
        EventRetractionHandle sendInteraction(InteractionClassHandle theInteraction,
                                              const ParameterHandleValuePairSet& theParameters,
                                              const FedTime& theTime, const char* theTag);
        void sendInteraction(InteractionClassHandle theInteraction, const ParameterHandleValuePairSet& theParameters,
                             const char* theTag);
        EventRetractionHandle deleteObjectInstance(ObjectHandle theObject, const FedTime& theTime,
                                                   const char* theTag);
        void deleteObjectInstance(ObjectHandle theObject, const char* theTag);
        void localDeleteObjectInstance(ObjectHandle theObject);
        void changeAttributeTransportationType(ObjectHandle theObject, const AttributeHandleSet& theAttributes,
                                               TransportationHandle theType);
        void changeInteractionTransportationType(InteractionClassHandle theClass, TransportationHandle theType);
        void requestObjectAttributeValueUpdate(ObjectHandle theObject, const AttributeHandleSet& theAttributes);
        void requestClassAttributeValueUpdate(ObjectClassHandle theClass, const AttributeHandleSet& theAttributes);

        // Ownership management (§7)
        void unconditionalAttributeOwnershipDivestiture(ObjectHandle theObject,
                                                        const AttributeHandleSet& theAttributes);
        void negotiatedAttributeOwnershipDivestiture(ObjectHandle theObject, const AttributeHandleSet& theAttributes,
                                                     const char* theTag);
        void attributeOwnershipAcquisition(ObjectHandle theObject, const AttributeHandleSet& desiredAttributes,
                                           const char* theTag);
        void attributeOwnershipAcquisitionIfAvailable(ObjectHandle theObject,
                                                      const AttributeHandleSet& desiredAttributes);
        // The attributes released (a new set; the caller deletes it).
        AttributeHandleSet* attributeOwnershipReleaseResponse(ObjectHandle theObject,
                                                              const AttributeHandleSet& theAttributes);
        void cancelNegotiatedAttributeOwnershipDivestiture(ObjectHandle theObject,
                                                           const AttributeHandleSet& theAttributes);
        void cancelAttributeOwnershipAcquisition(ObjectHandle theObject, const AttributeHandleSet& theAttributes);
        void queryAttributeOwnership(ObjectHandle theObject, AttributeHandle theAttribute);
        Boolean isAttributeOwnedByFederate(ObjectHandle theObject, AttributeHandle theAttribute);

        // Time management (§8)
        void enableTimeRegulation(const FedTime& theFederateTime, const FedTime& theLookahead);
        void disableTimeRegulation();
        void enableTimeConstrained();
        void disableTimeConstrained();
        void timeAdvanceRequest(const FedTime& theTime);
        void timeAdvanceRequestAvailable(const FedTime& theTime);
        void nextEventRequest(const FedTime& theTime);
        void nextEventRequestAvailable(const FedTime& theTime);
        void flushQueueRequest(const FedTime& theTime);
        void enableAsynchronousDelivery();
        void disableAsynchronousDelivery();
        void queryLBTS(FedTime& theTime);
        void queryFederateTime(FedTime& theTime);
        void queryMinNextEventTime(FedTime& theTime);
        void modifyLookahead(const FedTime& theLookahead);
        void queryLookahead(FedTime& theTime);
        void retract(EventRetractionHandle theHandle);
        void changeAttributeOrderType(ObjectHandle theObject, const AttributeHandleSet& theAttributes,
                                      OrderingHandle theType);
        void changeInteractionOrderType(InteractionClassHandle theClass, OrderingHandle theType);

        // Data distribution management (§9); hlacore's regions have one extent.
        Region* createRegion(SpaceHandle theSpace, ULong numberOfExtents);
        void notifyAboutRegionModification(Region& theRegion);
        void deleteRegion(Region* theRegion);
        ObjectHandle registerObjectInstanceWithRegion(ObjectClassHandle theClass, const char* theObject,
                                                      AttributeHandle theAttributes[], Region* theRegions[],
                                                      ULong theNumberOfHandles);
        ObjectHandle registerObjectInstanceWithRegion(ObjectClassHandle theClass, AttributeHandle theAttributes[],
                                                      Region* theRegions[], ULong theNumberOfHandles);
        void associateRegionForUpdates(Region& theRegion, ObjectHandle theObject,
                                       const AttributeHandleSet& theAttributes);
        void unassociateRegionForUpdates(Region& theRegion, ObjectHandle theObject);
        void subscribeObjectClassAttributesWithRegion(ObjectClassHandle theClass, Region& theRegion,
                                                      const AttributeHandleSet& attributeList,
                                                      Boolean active = RTI_TRUE);
        void unsubscribeObjectClassWithRegion(ObjectClassHandle theClass, Region& theRegion);
        void subscribeInteractionClassWithRegion(InteractionClassHandle theClass, Region& theRegion,
                                                 Boolean active = RTI_TRUE);
        void unsubscribeInteractionClassWithRegion(InteractionClassHandle theClass, Region& theRegion);
        EventRetractionHandle sendInteractionWithRegion(InteractionClassHandle theInteraction,
                                                        const ParameterHandleValuePairSet& theParameters,
                                                        const FedTime& theTime, const char* theTag,
                                                        const Region& theRegion);
        void sendInteractionWithRegion(InteractionClassHandle theInteraction,
                                       const ParameterHandleValuePairSet& theParameters, const char* theTag,
                                       const Region& theRegion);
        void requestClassAttributeValueUpdateWithRegion(ObjectClassHandle theClass,
                                                        const AttributeHandleSet& theAttributes,
                                                        const Region& theRegion);

        // Support services (§10); the names returned are new[]'d copies the caller deletes with delete[].
        ObjectClassHandle getObjectClassHandle(const char* theName);
        char* getObjectClassName(ObjectClassHandle theHandle);
        AttributeHandle getAttributeHandle(const char* theName, ObjectClassHandle whichClass);
        char* getAttributeName(AttributeHandle theHandle, ObjectClassHandle whichClass);
        InteractionClassHandle getInteractionClassHandle(const char* theName);
        char* getInteractionClassName(InteractionClassHandle theHandle);
        ParameterHandle getParameterHandle(const char* theName, InteractionClassHandle whichClass);
        char* getParameterName(ParameterHandle theHandle, InteractionClassHandle whichClass);
        ObjectHandle getObjectInstanceHandle(const char* theName);
        char* getObjectInstanceName(ObjectHandle theHandle);
        SpaceHandle getRoutingSpaceHandle(const char* theName);
        char* getRoutingSpaceName(SpaceHandle theHandle);
        DimensionHandle getDimensionHandle(const char* theName, SpaceHandle whichSpace);
        char* getDimensionName(DimensionHandle theHandle, SpaceHandle whichSpace);
        SpaceHandle getAttributeRoutingSpaceHandle(AttributeHandle theHandle, ObjectClassHandle whichClass);
        ObjectClassHandle getObjectClass(ObjectHandle theObject);
        SpaceHandle getInteractionRoutingSpaceHandle(InteractionClassHandle theHandle);
        TransportationHandle getTransportationHandle(const char* theName);
        char* getTransportationName(TransportationHandle theHandle);
        OrderingHandle getOrderingHandle(const char* theName);
        char* getOrderingName(OrderingHandle theHandle);
        void enableClassRelevanceAdvisorySwitch();
        void disableClassRelevanceAdvisorySwitch();
        void enableAttributeRelevanceAdvisorySwitch();
        void disableAttributeRelevanceAdvisorySwitch();
        void enableAttributeScopeAdvisorySwitch();
        void disableAttributeScopeAdvisorySwitch();
        void enableInteractionRelevanceAdvisorySwitch();
        void disableInteractionRelevanceAdvisorySwitch();

        // Delivers the callbacks that are ready, without waiting; RTI_TRUE when more are queued.
        Boolean tick();
        // Waits up to minimum seconds for a first callback, then delivers those that are ready for up to
        // maximum seconds in all; RTI_TRUE when more are queued.
        Boolean tick(TickTime minimum, TickTime maximum);

        RegionToken getRegionToken(Region* theRegion);
        Region* getRegion(RegionToken theToken);

        RTIambPrivateData* privateData;

    private:
        RTIambPrivateRefs* privateRefs;
    };

    // ---- the callbacks (HLA 1.3 §4-8), delivered by RTIambassador::tick ----
    class RTI_EXPORT FederateAmbassador {
    public:
        // noexcept(false): CERTI's federates declare theirs `throw (RTI::FederateInternalError)`, which an
        // implicitly noexcept destructor here would refuse as a looser exception specification.
        virtual ~FederateAmbassador() noexcept(false) {}

        // Federation management
        virtual void synchronizationPointRegistrationSucceeded(const char* label) = 0;
        virtual void synchronizationPointRegistrationFailed(const char* label) = 0;
        virtual void announceSynchronizationPoint(const char* label, const char* tag) = 0;
        virtual void federationSynchronized(const char* label) = 0;
        virtual void initiateFederateSave(const char* label) = 0;
        virtual void federationSaved() = 0;
        virtual void federationNotSaved() = 0;
        virtual void requestFederationRestoreSucceeded(const char* label) = 0;
        virtual void requestFederationRestoreFailed(const char* label, const char* reason) = 0;
        virtual void federationRestoreBegun() = 0;
        virtual void initiateFederateRestore(const char* label, FederateHandle handle) = 0;
        virtual void federationRestored() = 0;
        virtual void federationNotRestored() = 0;

        // Declaration management
        virtual void startRegistrationForObjectClass(ObjectClassHandle theClass) = 0;
        virtual void stopRegistrationForObjectClass(ObjectClassHandle theClass) = 0;
        virtual void turnInteractionsOn(InteractionClassHandle theHandle) = 0;
        virtual void turnInteractionsOff(InteractionClassHandle theHandle) = 0;

        // Object management
        virtual void discoverObjectInstance(ObjectHandle theObject, ObjectClassHandle theObjectClass,
                                            const char* theObjectName) = 0;
        virtual void reflectAttributeValues(ObjectHandle theObject, const AttributeHandleValuePairSet& theAttributes,
                                            const FedTime& theTime, const char* theTag,
                                            EventRetractionHandle theHandle) = 0;
        virtual void reflectAttributeValues(ObjectHandle theObject, const AttributeHandleValuePairSet& theAttributes,
                                            const char* theTag) = 0;
        virtual void receiveInteraction(InteractionClassHandle theInteraction,
                                        const ParameterHandleValuePairSet& theParameters, const FedTime& theTime,
                                        const char* theTag, EventRetractionHandle theHandle) = 0;
        virtual void receiveInteraction(InteractionClassHandle theInteraction,
                                        const ParameterHandleValuePairSet& theParameters, const char* theTag) = 0;
        virtual void removeObjectInstance(ObjectHandle theObject, const FedTime& theTime, const char* theTag,
                                          EventRetractionHandle theHandle) = 0;
        virtual void removeObjectInstance(ObjectHandle theObject, const char* theTag) = 0;
        virtual void attributesInScope(ObjectHandle theObject, const AttributeHandleSet& theAttributes) = 0;
        virtual void attributesOutOfScope(ObjectHandle theObject, const AttributeHandleSet& theAttributes) = 0;
        virtual void provideAttributeValueUpdate(ObjectHandle theObject, const AttributeHandleSet& theAttributes) = 0;
        virtual void turnUpdatesOnForObjectInstance(ObjectHandle theObject, const AttributeHandleSet& theAttributes) = 0;
        virtual void turnUpdatesOffForObjectInstance(ObjectHandle theObject, const AttributeHandleSet& theAttributes) = 0;

        // Ownership management
        virtual void requestAttributeOwnershipAssumption(ObjectHandle theObject,
                                                         const AttributeHandleSet& offeredAttributes,
                                                         const char* theTag) = 0;
        virtual void attributeOwnershipDivestitureNotification(ObjectHandle theObject,
                                                               const AttributeHandleSet& releasedAttributes) = 0;
        virtual void attributeOwnershipAcquisitionNotification(ObjectHandle theObject,
                                                               const AttributeHandleSet& securedAttributes) = 0;
        virtual void attributeOwnershipUnavailable(ObjectHandle theObject, const AttributeHandleSet& theAttributes) = 0;
        virtual void requestAttributeOwnershipRelease(ObjectHandle theObject,
                                                      const AttributeHandleSet& candidateAttributes,
                                                      const char* theTag) = 0;
        virtual void confirmAttributeOwnershipAcquisitionCancellation(ObjectHandle theObject,
                                                                      const AttributeHandleSet& theAttributes) = 0;
        virtual void informAttributeOwnership(ObjectHandle theObject, AttributeHandle theAttribute,
                                              FederateHandle theOwner) = 0;
        virtual void attributeIsNotOwned(ObjectHandle theObject, AttributeHandle theAttribute) = 0;
        virtual void attributeOwnedByRTI(ObjectHandle theObject, AttributeHandle theAttribute) = 0;

        // Time management
        virtual void timeRegulationEnabled(const FedTime& theFederateTime) = 0;
        virtual void timeConstrainedEnabled(const FedTime& theFederateTime) = 0;
        virtual void timeAdvanceGrant(const FedTime& theTime) = 0;
        virtual void requestRetraction(EventRetractionHandle theHandle) = 0;
    };
};

#undef RTI_EXCEPT

#define MAX_FEDERATION "macro variable is deprecated"
#define MAX_FEDERATE "macro variable is deprecated"
#define MAX_NAME_LENGTH "macro variable is deprecated"
#define MAX_SPACES "macro variable is deprecated"
#define MAX_OBJECT_CLASSES "macro variable is deprecated"
#define MAX_INTERACTION_CLASSES "macro variable is deprecated"
#define MAX_ATTRIBUTES_PER_CLASS "macro variable is deprecated"
#define MAX_PARAMETERS_PER_CLASS "macro variable is deprecated"
#define MAX_DIMENSIONS_PER_SPACE "macro variable is deprecated"
#define MAX_USER_TAG_LENGTH "macro variable is deprecated"
#define DEFAULT_SPACE_NAME "defaultSpace"
#define DEFAULT_SPACE_DIMENSION_NAME "dimension"
#define RTI_VERSION "hlacore HLA 1.3"
#define RTI_INTERNAL_VERSION "hlacore HLA 1.3"
#define RTI_MAJOR_VERSION 1
#define RTI_MINOR_VERSION 3
#define RTI_RELEASE 0
#define RTI_INTERNAL_MAJOR_VERSION 1
#define RTI_INTERNAL_MINOR_VERSION 3
#define RTI_INTERNAL_RELEASE 0
// The bounds of a region's ranges (HLA 1.3 §9: the axis of every dimension).
#define MIN_EXTENT ((RTI::ULong)0UL)
#define MAX_EXTENT ((RTI::ULong)0xFFFFFFFFUL)

RTI_STD::ostream RTI_EXPORT& operator<<(RTI_STD::ostream& os, const RTI::Exception* ex);
RTI_STD::ostream RTI_EXPORT& operator<<(RTI_STD::ostream& os, const RTI::Exception& ex);

#endif
