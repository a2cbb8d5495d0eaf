// A federate in the style of CERTI's HLA 1.3 examples (test/Billard): C++98 with exception specifications
// on the callbacks and the destructor, RTI_USES_STD_FSTREAM, NullFederateAmbassador, RTIfedTime, tick(min, max). It is kept
// as such: tests/system/test_cpp_api.py builds it unchanged against hlacore (g++ -std=gnu++14
// -DRTI_USES_STD_FSTREAM and the flags of python -m hlacore.config) and runs two of them.
//
// usage: billiard NAME STEPS FED_FILE [--creator]
// Each federate rolls a ball (class Bille) and updates its position with a timestamp every step; every
// fifth step it sends a Bing. Once it has seen another ball, each federate turns its time management on;
// the creator then registers the synchronization point "Init", and both advance in lockstep from there. At the end it prints
// "done NAME STEPS REFLECTIONS BINGS", the other ball's updates and Bings received.
#include <RTI.hh>
#include <fedtime.hh>
#include <NullFederateAmbassador.hh>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include <unistd.h>

using std::cout;
using std::endl;

class BilliardAmbassador : public NullFederateAmbassador
{
public:
    BilliardAmbassador()
        : granted(false), announced(false), synchronized(false), regulating(false), constrained(false),
          otherBall(0), reflections(0), bings(0), late(0), grantedTime(0.0) {}
    virtual ~BilliardAmbassador() throw (RTI::FederateInternalError) {}

    bool granted, announced, synchronized, regulating, constrained;
    RTI::ObjectHandle otherBall;
    int reflections, bings, late;
    double grantedTime;

    void announceSynchronizationPoint(const char *label, const char *)
        throw (RTI::FederateInternalError)
    {
        if (strcmp(label, "Init") == 0) announced = true;
    }

    void federationSynchronized(const char *label)
        throw (RTI::FederateInternalError)
    {
        if (strcmp(label, "Init") == 0) synchronized = true;
    }

    void discoverObjectInstance(RTI::ObjectHandle theObject, RTI::ObjectClassHandle, const char *theName)
        throw (RTI::CouldNotDiscover, RTI::ObjectClassNotKnown, RTI::FederateInternalError)
    {
        cout << "discovered " << theName << endl;
        otherBall = theObject;
    }

    void reflectAttributeValues(RTI::ObjectHandle, const RTI::AttributeHandleValuePairSet &theAttributes,
                                const RTI::FedTime &theTime, const char *, RTI::EventRetractionHandle)
        throw (RTI::ObjectNotKnown, RTI::AttributeNotKnown, RTI::FederateOwnsAttributes,
               RTI::InvalidFederationTime, RTI::FederateInternalError)
    {
        // A position is never stamped beyond the grant being waited for.
        if (((const RTIfedTime &) theTime).getTime() <= grantedTime) late++;
        for (unsigned int i = 0; i < theAttributes.size(); i++) {
            RTI::ULong length;
            char *value = theAttributes.getValuePointer(i, length);
            if (length != sizeof(double)) late++;
            (void) value;
        }
        reflections++;
    }

    // Before this federate is time-constrained, timestamped updates come in receive order, without their time.
    void reflectAttributeValues(RTI::ObjectHandle, const RTI::AttributeHandleValuePairSet &, const char *)
        throw (RTI::ObjectNotKnown, RTI::AttributeNotKnown, RTI::FederateOwnsAttributes, RTI::FederateInternalError)
    {
        reflections++;
    }

    void receiveInteraction(RTI::InteractionClassHandle, const RTI::ParameterHandleValuePairSet &theParameters,
                            const RTI::FedTime &, const char *, RTI::EventRetractionHandle)
        throw (RTI::InteractionClassNotKnown, RTI::InteractionParameterNotKnown, RTI::InvalidFederationTime,
               RTI::FederateInternalError)
    {
        if (theParameters.size() == 3) bings++;
    }

    void timeRegulationEnabled(const RTI::FedTime &)
        throw (RTI::InvalidFederationTime, RTI::EnableTimeRegulationWasNotPending, RTI::FederateInternalError)
    {
        regulating = true;
    }

    void timeConstrainedEnabled(const RTI::FedTime &)
        throw (RTI::InvalidFederationTime, RTI::EnableTimeConstrainedWasNotPending, RTI::FederateInternalError)
    {
        constrained = true;
    }

    void timeAdvanceGrant(const RTI::FedTime &theTime)
        throw (RTI::InvalidFederationTime, RTI::TimeAdvanceWasNotInProgress, RTI::FederateInternalError)
    {
        granted = true;
        grantedTime = ((const RTIfedTime &) theTime).getTime();
    }
};

static void tickUntil(RTI::RTIambassador &rtia, bool &flag, const char *what)
{
    for (int i = 0; !flag; i++) {
        if (i > 2000) {  // 2000 ticks of at most 0.05 s
            std::cerr << "billiard: no " << what << endl;
            exit(1);
        }
        rtia.tick(0.01, 0.05);
    }
}

static void put(RTI::AttributeHandleValuePairSet *set, RTI::AttributeHandle h, double value)
{
    set->add(h, (const char *) &value, sizeof(value));
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        std::cerr << "usage: billiard NAME STEPS FED_FILE [--creator]" << endl;
        return 2;
    }
    std::string name = argv[1];
    int steps = atoi(argv[2]);
    bool creator = argc > 4 && strcmp(argv[4], "--creator") == 0;

    try {
        RTI::RTIambassador rtia;
        BilliardAmbassador fedamb;

        if (creator) {
            try {
                rtia.createFederationExecution("Test", argv[3]);
            }
            catch (RTI::FederationExecutionAlreadyExists &e) {
                cout << "federation already exists: " << e._reason << endl;
            }
        }
        // As CERTI's examples do: try again while the creator has not created it yet.
        for (int attempt = 0;; attempt++) {
            try {
                rtia.joinFederationExecution(name.c_str(), "Test", &fedamb);
                break;
            }
            catch (RTI::FederationExecutionDoesNotExist &) {
                if (attempt == 100) throw;
                usleep(50000);
            }
        }

        RTI::ObjectClassHandle bille = rtia.getObjectClassHandle("Bille");
        RTI::AttributeHandle posX = rtia.getAttributeHandle("PositionX", bille);
        RTI::AttributeHandle posY = rtia.getAttributeHandle("PositionY", bille);
        RTI::InteractionClassHandle bing = rtia.getInteractionClassHandle("Bing");
        RTI::ParameterHandle boulNum = rtia.getParameterHandle("BoulNum", bing);
        RTI::ParameterHandle dx = rtia.getParameterHandle("DX", bing);
        RTI::ParameterHandle dy = rtia.getParameterHandle("DY", bing);

        RTI::AttributeHandleSet *attributes = RTI::AttributeHandleSetFactory::create(2);
        attributes->add(posX);
        attributes->add(posY);
        rtia.subscribeObjectClassAttributes(bille, *attributes, RTI::RTI_TRUE);
        rtia.publishObjectClass(bille, *attributes);
        rtia.subscribeInteractionClass(bing, RTI::RTI_TRUE);
        rtia.publishInteractionClass(bing);
        delete attributes;
        RTI::ObjectHandle ball = rtia.registerObjectInstance(bille, name.c_str());

        bool otherSeen = false;
        while (!otherSeen) {
            rtia.tick(0.01, 0.05);
            otherSeen = fedamb.otherBall != 0;
        }
        RTIfedTime lookahead(1.0);
        RTIfedTime now(0.0);
        rtia.enableTimeRegulation(now, lookahead);
        tickUntil(rtia, fedamb.regulating, "timeRegulationEnabled");
        rtia.enableTimeConstrained();
        tickUntil(rtia, fedamb.constrained, "timeConstrainedEnabled");

        // Both regulating and constrained before the first step: the creator's "Init" is achieved by each
        // federate once its time management is on.
        if (creator) rtia.registerFederationSynchronizationPoint("Init", "");
        tickUntil(rtia, fedamb.announced, "Init announcement");
        rtia.synchronizationPointAchieved("Init");
        tickUntil(rtia, fedamb.synchronized, "Init synchronization");

        double x = 0.0, y = 0.0;
        for (int step = 1; step <= steps; step++) {
            RTIfedTime next(now);
            next += lookahead;
            x += 1.5;
            y -= 0.5;
            RTI::AttributeHandleValuePairSet *position = RTI::AttributeSetFactory::create(2);
            put(position, posX, x);
            put(position, posY, y);
            rtia.updateAttributeValues(ball, *position, next, "position");
            delete position;
            if (step % 5 == 0) {
                RTI::ParameterHandleValuePairSet *parameters = RTI::ParameterSetFactory::create(3);
                long number = step;
                parameters->add(boulNum, (const char *) &number, sizeof(number));
                parameters->add(dx, (const char *) &x, sizeof(x));
                parameters->add(dy, (const char *) &y, sizeof(y));
                rtia.sendInteraction(bing, *parameters, next, "bing");
                delete parameters;
            }
            fedamb.granted = false;
            rtia.timeAdvanceRequest(next);
            tickUntil(rtia, fedamb.granted, "timeAdvanceGrant");
            now = fedamb.grantedTime;
        }

        cout << "done " << name << " " << now.getTime() << " " << fedamb.reflections << " " << fedamb.bings << " "
             << fedamb.late << endl;
        rtia.resignFederationExecution(RTI::DELETE_OBJECTS);
        if (creator) {
            for (int attempt = 0;; attempt++) {
                try {
                    rtia.destroyFederationExecution("Test");
                    break;
                }
                catch (RTI::FederatesCurrentlyJoined &) {
                    if (attempt == 100) throw;
                    usleep(50000);
                }
            }
        }
    }
    catch (RTI::Exception &e) {
        std::cerr << "billiard: " << &e << endl;
        return 1;
    }
    return 0;
}
