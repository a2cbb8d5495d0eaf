# The sending half (see uav-receive.py): registers one object and updates it COUNT times, ticking.
import sys

import hla.rti
import hla.omt as fom


class MyAmbassador(hla.rti.FederateAmbassador):
    def provideAttributeValueUpdate(self, object, attributes):
        print("PROVIDE", rtia.getObjectInstanceName(object), flush=True)


count = int(sys.argv[1])
fedfile = sys.argv[2]
rtia = hla.rti.RTIAmbassador()
try:
    rtia.createFederationExecution("uav", fedfile)
except hla.rti.FederationExecutionAlreadyExists:
    pass

mya = MyAmbassador()
rtia.joinFederationExecution("uav-send", "uav", mya)

classHandle = rtia.getObjectClassHandle("SampleClass")
classHandle_A = rtia.getAttributeHandle("AttributeA", classHandle)
classHandle_B = rtia.getAttributeHandle("AttributeB", classHandle)
rtia.publishObjectClass(classHandle, [classHandle_A, classHandle_B])
myObject = rtia.registerObjectInstance(classHandle, "HAF")

for step in range(count):
    rtia.updateAttributeValues(myObject,
        {classHandle_A: fom.HLAfloat32BE.pack(3.14 + step), classHandle_B: fom.HLAfloat32BE.pack(2.72)},
        "update")
    rtia.tick(0.01, 0.05)

rtia.deleteObjectInstance(myObject, "delete")
rtia.resignFederationExecution(hla.rti.ResignAction.DeleteObjectsAndReleaseAttributes)
try:
    rtia.destroyFederationExecution("uav")
except hla.rti.FederatesCurrentlyJoined:
    pass
print("Done.")
