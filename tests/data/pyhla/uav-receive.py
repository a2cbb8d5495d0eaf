# A PyHLA federate as PyHLA users write them (import hla.rti, hla.omt, typed handles, tick):
# run unchanged by `python -m hlacore.pyhla uav-receive.py COUNT`. It prints "ready" once subscribed,
# then one line per reflection, and exits after COUNT of them.
import sys

import hla.rti
import hla.omt as fom


class MyAmbassador(hla.rti.FederateAmbassador):
    def __init__(self):
        self.reflected = 0

    def discoverObjectInstance(self, object, objectClass, objectName):
        print("DISCOVER", objectName, rtia.getObjectClassName(objectClass), flush=True)

    def reflectAttributeValues(self, object, attributes, tag, order, transport, time=None, retraction=None):
        a, size = fom.HLAfloat32BE.unpack(attributes[classHandle_A])
        b, size = fom.HLAfloat32BE.unpack(attributes[classHandle_B])
        print("REFLECT", a, b, tag, flush=True)
        self.reflected += 1


count = int(sys.argv[1])
fedfile = sys.argv[2]
print("Create ambassador")
rtia = hla.rti.RTIAmbassador()
try:
    rtia.createFederationExecution("uav", fedfile)
    print("Federation created.")
except hla.rti.FederationExecutionAlreadyExists:
    print("Federation already exists.")

mya = MyAmbassador()
rtia.joinFederationExecution("uav-recv", "uav", mya)

classHandle = rtia.getObjectClassHandle("SampleClass")
classHandle_A = rtia.getAttributeHandle("AttributeA", classHandle)
classHandle_B = rtia.getAttributeHandle("AttributeB", classHandle)
rtia.subscribeObjectClassAttributes(classHandle, [classHandle_A, classHandle_B])
print("ready", flush=True)

while mya.reflected < count:
    rtia.tick(1.0, 1.0)

rtia.resignFederationExecution(hla.rti.ResignAction.DeleteObjectsAndReleaseAttributes)
print("Done.")
