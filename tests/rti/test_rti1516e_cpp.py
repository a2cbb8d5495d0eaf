"""IEEE 1516-2010 in C++ (librti1516e, docs/rti1516e.md): a federate built against the installed headers and
libraries through the CMake package (tests/cpp/rti1516e, built by ./scripts/test.sh), in one federation with
a Python 1516-2010 federate, a Python HLA 1.3 one and a C++ HLA 1.3 one (tests/cpp/hla13): the services whose
answers it knows, then a 1 000-step timestamped lockstep of the four; and the flags of
``python -m hlacore.config --api 1516e`` and pkg-config."""

from __future__ import annotations

import os
import pathlib
import re
import shutil
import subprocess
import sys
import time
from typing import Any

import hlacore.rti as rti
import hlacore.rti1516e as rti1516e
from hlacore import config
from hlacore.processes import Child

from support import ROOT, RtigProcess, cpp_federate, rti1516e_program as program
from support.rti1516e import CARS, VEHICLES, Recorder


def test_the_exceptions_and_their_renaming_are_the_same_in_python_and_cpp() -> None:
    """The two APIs name the same exceptions, and rename the core's the same way: the Python module's lists held
    to the C++ header's RTI1516E_EXCEPTIONS and cpp/rti1516e/types.cpp's HLACORE_RENAMED."""
    header = (ROOT / "cpp" / "rti1516e" / "include" / "RTI" / "Exception.h").read_text()
    listed = header[header.index("#define RTI1516E_EXCEPTIONS(X)"):header.index("#define RTI_EXCEPTION(A)")]
    assert re.findall(r"X\((\w+)\)", listed) == list(rti1516e._exceptions.NAMES)
    types = (ROOT / "cpp" / "rti1516e" / "types.cpp").read_text()
    renamed = types[types.index("#define HLACORE_RENAMED(X)"):types.index("std::string renamed(")]
    assert dict(re.findall(r"X\((\w+), (\w+)\)", renamed)) == rti1516e._exceptions._RENAMED


def test_four_federates_of_both_apis_and_languages_in_a_1000_step_lockstep(rtig: RtigProcess) -> None:
    """1516-2010 and HLA 1.3, Python and C++: four federates, each regulating and constrained with lookahead 1,
    each updating its vehicle's position at t before asking for t: every grant of each comes after the three
    others' updates at its time."""
    steps = 1000
    amb = Recorder()
    new = rti1516e.RTIambassador()
    new.connect(amb, "HLA_EVOKED", rtig.address)
    new.createFederationExecution("Vehicles", [VEHICLES, CARS])
    new.joinFederationExecution("python-1516e", "test", "Vehicles")
    old_amb = Recorder()
    old = rti.RTIAmbassador(rtig.address)
    old.joinFederationExecution("python-13", "Vehicles", old_amb)  # type: ignore[arg-type]
    with Child([program("rti1516e_federate"), rtig.address, "cpp", str(steps), "3"]) as cpp, \
            Child([cpp_federate("hla13_lockstep_federate"), "Vehicles", "cpp-13", str(steps), "3"],
                  env={**os.environ, "HLACORE_RTIG": rtig.address}) as cpp13:
        try:
            ready = cpp.read_json(timeout=60)
            assert ready == {"ready": True, "time": 0}, cpp.stderr()
            assert cpp13.read_json(timeout=60) == {"ready": True}, cpp13.stderr()
            vehicle = new.getObjectClassHandle("Vehicle")
            position = new.getAttributeHandle(vehicle, "position")
            new.publishObjectClassAttributes(vehicle, [position])
            new.subscribeObjectClassAttributes(vehicle, [position])
            new.enableTimeRegulation(1.0)
            new.enableTimeConstrained()
            old_vehicle = old.getObjectClassHandle("Vehicle")
            old_position = old.getAttributeHandle("position", old_vehicle)
            old.publishObjectClass(old_vehicle, [old_position])
            old.subscribeObjectClassAttributes(old_vehicle, [old_position])
            old.enable_time_management(1.0)

            def pump(done: Any, what: str) -> None:
                deadline = time.monotonic() + 60
                while not done():
                    assert time.monotonic() < deadline, f"{what}: {cpp.stderr()}"
                    new.evokeMultipleCallbacks(0.0, 0.02)
                    old.tick(0.0, 0.02)

            pump(lambda: amb.last("timeConstrainedEnabled") is not None, "time management")
            new.reserveObjectInstanceName("python-1516e-vehicle")
            pump(lambda: amb.last("objectInstanceNameReservationSucceeded") is not None, "reservation")
            mine = new.registerObjectInstance(vehicle, "python-1516e-vehicle")
            theirs = old.registerObjectInstance(old_vehicle, "python-13-vehicle")
            new.registerFederationSynchronizationPoint("go", b"")
            pump(lambda: amb.last("announceSynchronizationPoint") is not None, "go announced")
            new.synchronizationPointAchieved("go")
            old.synchronizationPointAchieved("go")
            pump(lambda: amb.last("federationSynchronized") is not None, "go synchronized")
            for step in range(1, steps + 1):
                t = float(step)
                new.updateAttributeValues(mine, {position: b"python-1516e %d" % step}, b"", t)
                old.updateAttributeValues(theirs, {old_position: b"python-13 %d" % step}, "", t)
                new.timeAdvanceRequest(t)
                old.timeAdvanceRequest(t)
                pump(lambda: amb.last("timeAdvanceGrant") == (t,) and old_amb.last("timeAdvanceGrant") == (t,),
                     f"step {step}")
            summaries = [cpp.read_json(timeout=60), cpp13.read_json(timeout=60)]
            assert cpp.wait(timeout=30) == 0, cpp.stderr()
            assert cpp13.wait(timeout=30) == 0, cpp13.stderr()
        finally:
            old.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
            new.resignFederationExecution(rti1516e.CANCEL_THEN_DELETE_THEN_DIVEST)
            new.disconnect()
    assert summaries == [{"steps": steps, "reflections": 3 * steps, "late": 0}] * 2
    # The Python sides, in the order delivered: each grant at t after the three others' updates at t.
    for calls, time_of in ((amb.calls, 5), (old_amb.calls, 5)):
        at: dict[float, int] = {}
        grants = 0
        for name, args in calls:
            if name == "reflectAttributeValues" and len(args) > time_of and args[time_of] is not None:
                at[args[time_of]] = at.get(args[time_of], 0) + 1
            elif name == "timeAdvanceGrant" and args[0] > 0:
                grants += 1
                assert at.get(args[0]) == 3, f"grant {args[0]} after {at.get(args[0])} updates at its time"
        assert grants == steps


def test_the_flags_of_hlacore_config_and_pkg_config_build_a_1516e_federate(tmp_path: pathlib.Path) -> None:
    """The same federate built by hand with ``python -m hlacore.config --api 1516e --cflags --libs`` and with
    ``pkg-config hlacore-rti1516e``: both link and name the installed libraries."""
    flags = subprocess.run([sys.executable, "-m", "hlacore.config", "--api", "1516e", "--cflags", "--libs"],
                           capture_output=True, text=True, check=True).stdout.split()
    assert flags == config.cflags("1516e") + config.libs("1516e")
    assert (config.include_dir("1516e") / "RTI" / "RTIambassador.h").is_file()
    source = ROOT / "tests" / "cpp" / "rti1516e" / "federate.cpp"
    compiler = shutil.which("c++") or "g++"
    built = subprocess.run([compiler, "-std=c++17", str(source), *flags, "-o", str(tmp_path / "by_config")],
                           capture_output=True, text=True, timeout=300)
    assert built.returncode == 0, built.stderr
    pc = subprocess.run(["pkg-config", "--cflags", "--libs", "hlacore-rti1516e"], capture_output=True, text=True,
                        env={**os.environ, "PKG_CONFIG_PATH": str(config.pkg_config_dir())}, check=True).stdout.split()
    assert "-lrti1516e" in pc and "-lfedtime1516e" in pc
    usage = subprocess.run([str(tmp_path / "by_config")], capture_output=True, text=True, timeout=30)
    assert usage.returncode == 2 and "usage: rti1516e_federate" in usage.stderr
