"""Joins TestFed and blocks in tick(30, 30); prints 'interrupted' when Ctrl-C (SIGINT) ends the wait."""

import sys
import time

import hlacore.rti as rti

rtia = rti.RTIAmbassador(sys.argv[1])
rtia.joinFederationExecution("sleeper", "TestFed", rti.FederateAmbassador())
print("ticking", flush=True)
start = time.monotonic()
try:
    rtia.tick(30.0, 30.0)
    print("tick returned", flush=True)
except KeyboardInterrupt:
    print(f"interrupted after {time.monotonic() - start:.1f} s", flush=True)
rtia.resignFederationExecution(rti.ResignAction.NoAction)
