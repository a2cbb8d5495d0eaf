"""The HLA 1.3 C++ API (libRTI-NG, docs/cpp-api.md): every service called from C++ through rtig, a C++ and a
Python federate in one federation over both gateways, a CERTI-style federate built unchanged with the
flags of ``python -m hlacore.config`` and of pkg-config, and the CMake package (the test federates of
tests/cpp/hla13 are built through it by ./scripts/test.sh)."""

from __future__ import annotations

import os
import re
import pathlib
import subprocess
import sys
from typing import Any

import pytest

from hlacore import _core, config
from hlacore.processes import Child

from support import DATA, ROOT, TESTS, RtigProcess, cpp_federate, tick_until

BILLIARD = TESTS / "cpp" / "hla13" / "certi_style" / "billiard.cc"
BILLIARD_FED = DATA / "fed" / "good" / "billard_certi.fed"


def gateway_env(address: str) -> dict[str, str]:
    return {**os.environ, "HLACORE_RTIG": address}


@pytest.mark.parametrize("busy_poll_us", ["0", "50"])
def test_every_service_from_cpp(rtig: RtigProcess, busy_poll_us: str) -> None:
    """Every service from C++, as it is by default and busy polling ($HLACORE_BUSY_POLL_US)."""
    run = subprocess.run([cpp_federate("hla13_services"), str(DATA / "ddm.fed")],
                         env={**gateway_env(rtig.address), "HLACORE_BUSY_POLL_US": busy_poll_us},
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout + run.stderr
    assert run.stdout == "called 102 services\n"


def test_a_bad_busy_poll_variable_is_an_rti_internal_error(rtig: RtigProcess) -> None:
    run = subprocess.run([cpp_federate("hla13_services"), str(DATA / "ddm.fed")],
                         env={**gateway_env(rtig.address), "HLACORE_BUSY_POLL_US": "100001"},
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 1
    assert "unexpected RTIinternalError: $HLACORE_BUSY_POLL_US='100001': busy polling must be a whole number of µs" in run.stderr


def test_no_gateway_is_an_rti_internal_error() -> None:
    """RTIambassador() with nothing listening throws RTI::RTIinternalError naming the address."""
    run = subprocess.run([cpp_federate("hla13_services"), str(DATA / "ddm.fed")],
                         env=gateway_env("127.0.0.1:9"), capture_output=True, text=True, timeout=60)
    assert run.returncode == 1
    assert "unexpected RTIinternalError: " in run.stderr and "127.0.0.1:9" in run.stderr


def reflected(fed: Any, value: bytes) -> bool:
    return any(value in args[1].values() for args in fed.amb.named("reflectAttributeValues"))


def received(fed: Any, value: bytes) -> bool:
    return any(value in args[1].values() for args in fed.amb.named("receiveInteraction"))


def test_cpp_and_python_federates_in_one_federation(gateway_address: str, federation: Any) -> None:
    """Updates and interactions both ways in receive order, a 1 MiB update each way, then a TSO lockstep of
    1000 steps in which every grant, on both sides, comes after the other federate's update at its time."""
    steps = 1000
    py = federation("python")
    robot = py.rtia.getObjectClassHandle("robot")
    location = py.rtia.getAttributeHandle("location", robot)
    command = py.rtia.getInteractionClassHandle("command")
    value = py.rtia.getParameterHandle("value", command)
    py.rtia.publishObjectClass(robot, [location])
    py.rtia.subscribeObjectClassAttributes(robot, [location])
    py.rtia.publishInteractionClass(command)
    py.rtia.subscribeInteractionClass(command)
    obj = py.rtia.registerObjectInstance(robot, "python")
    with Child([cpp_federate("hla13_mixed_federate"), "TestFed", "cpp", str(steps)],
               env=gateway_env(gateway_address)) as cpp:
        assert cpp.read_json(timeout=30) == {"ready": True}

        def synchronize(label: str, count: int) -> None:
            py.rtia.registerFederationSynchronizationPoint(label, "")
            tick_until(lambda: len(py.amb.named("announceSynchronizationPoint")) == count, py.rtia)
            py.rtia.synchronizationPointAchieved(label)
            tick_until(lambda: len(py.amb.named("federationSynchronized")) == count, py.rtia, timeout=30)

        synchronize("start", 1)
        py.rtia.updateAttributeValues(obj, {location: b"hello from python"}, "ro")
        py.rtia.sendInteraction(command, {value: b"hello from python"}, "ro")
        tick_until(lambda: reflected(py, b"hello from cpp") and received(py, b"hello from cpp"), py.rtia, timeout=30)
        camera = bytes(i % 251 for i in range(1 << 20))  # the same bytes as the C++ federate's
        py.rtia.updateAttributeValues(obj, {location: camera}, "camera")
        tick_until(lambda: reflected(py, camera), py.rtia, timeout=30)
        py.enable_time(1.0)
        synchronize("timed", 2)
        for step in range(1, steps + 1):
            py.rtia.updateAttributeValues(obj, {location: b"python %d" % step}, "", float(step))
            assert py.rtia.advance_to(float(step), timeout=30) == step
        summary = cpp.read_json(timeout=60)
        assert cpp.wait(timeout=30) == 0, cpp.stderr()
    assert summary == {"steps": steps, "reflections": steps, "late": 0}
    # This side, in the order delivered: each grant at t right after the C++ federate's update at t.
    last: Any = None
    grants = 0
    for name, args in py.amb.calls:
        if name == "reflectAttributeValues" and len(args) > 5:
            last = (args[1][location], args[5])
        elif name == "timeAdvanceGrant":
            grants += 1
            assert last == (b"cpp %d" % args[0], args[0]), f"grant {args[0]} after {last}"
    assert grants == steps


def build_billiard(tmp_path: pathlib.Path, flags: list[str], name: str) -> str:
    """billiard.cc as CERTI's examples are built (C++14 for the exception specifications, RTI_USES_STD_FSTREAM)."""
    binary = tmp_path / name
    build = subprocess.run(["g++", "-std=gnu++14", "-Wno-deprecated", "-DRTI_USES_STD_FSTREAM", str(BILLIARD),
                            *flags, "-o", str(binary)], capture_output=True, text=True, timeout=300)
    assert build.returncode == 0, build.stderr
    return str(binary)


def play_billiard(binary: str, address: str, steps: int = 30) -> None:
    env = gateway_env(address)
    with Child([binary, "b1", str(steps), str(BILLIARD_FED), "--creator"], env=env) as b1, \
            Child([binary, "b2", str(steps), str(BILLIARD_FED)], env=env) as b2:
        for name, child in (("b1", b1), ("b2", b2)):
            lines = [child.read_line(timeout=60) for _ in range(2)]
            other = "b2" if name == "b1" else "b1"
            # Each saw the other ball, every one of its updates and its Bings, none late.
            assert lines == [f"discovered {other}", f"done {name} {steps} {steps} {steps // 5} 0"], child.stderr()
            assert child.wait(timeout=30) == 0, child.stderr()


def test_certi_style_federate_builds_with_the_config_flags(tmp_path: pathlib.Path, rtig: RtigProcess) -> None:
    flags = subprocess.run([sys.executable, "-m", "hlacore.config", "--cflags", "--libs"], capture_output=True,
                           text=True, check=True).stdout.split()
    assert flags == config.cflags() + config.libs()
    play_billiard(build_billiard(tmp_path, flags, "billiard"), rtig.address)


def test_certi_style_federate_builds_with_pkg_config(tmp_path: pathlib.Path, rtig: RtigProcess) -> None:
    env = {**os.environ, "PKG_CONFIG_PATH": str(config.pkg_config_dir())}
    flags = subprocess.run(["pkg-config", "--cflags", "--libs", "hlacore"], env=env, capture_output=True, text=True,
                           check=True).stdout.split()
    play_billiard(build_billiard(tmp_path, flags, "billiard-pc"), rtig.address)


def test_config_without_an_option_says_what_to_ask() -> None:
    run = subprocess.run([sys.executable, "-m", "hlacore.config"], capture_output=True, text=True)
    assert run.returncode == 2 and "--cflags" in run.stderr


def test_the_exceptions_are_hlacores() -> None:
    """RTI.hh declares the HLA 1.3 exceptions of hlacore's list (cpp/rti/exceptions.hpp), hlacore's own after
    ValueLengthExceeded aside (they reach C++ as RTIinternalError naming them)."""
    header = (config.include_dir() / "RTI.hh").read_text()
    declared = re.findall(r"^\s*RTI_EXCEPT\((\w+)\)$", header, re.MULTILINE)
    listed = (ROOT / "cpp" / "rti" / "exceptions.hpp").read_text()
    listed = listed[listed.index("#define HLACORE_EXCEPTIONS"):listed.index("namespace hlacore")]
    ours = re.findall(r"X\((\w+)\)", listed)
    assert declared == ours[:ours.index("ValueLengthExceeded") + 1]
    assert len(declared) == 79


def test_the_callbacks_are_hlacores() -> None:
    """FederateAmbassador declares each callback of hlacore's list (cpp/rti/wire/callbacks.hpp) as pure
    virtual, the timed and untimed reflect, receive and remove as two each."""
    header = (config.include_dir() / "RTI.hh").read_text()
    ambassador = header[header.index("class RTI_EXPORT FederateAmbassador {"):]
    declared = re.findall(r"virtual void (\w+)\(", ambassador)
    assert sorted(set(declared)) == sorted(_core.CALLBACKS)
    assert len(declared) == len(_core.CALLBACKS) + 3
    assert ambassador.count(") = 0;") == len(declared)
