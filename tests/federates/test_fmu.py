"""hlacore.fmu: FMI 2 and FMI 3 co-simulation FMUs (tests/data/fmu/lag2, lag3, compiled by the test) as federates.
Against a feeder federate one gives fmpy.simulate_fmu's trajectory on the same input, by attributes or by
interactions; two coupled through the federation give the coupled system; a save and a restore mid-run end
where the run did; the command line writes the FOM and runs; each bad input is refused with its error before
joining, or after a clean resign, leaving nothing behind."""

from __future__ import annotations

import contextlib
import dataclasses
import math
import os
import pathlib
import subprocess
import sys
import tempfile
import threading
import zipfile
from typing import Any, Callable, Iterator

import fmpy  # the test extra installs it
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import hlacore
from hlacore import omt, rti
from hlacore.fmu import (
    Endpoint, FmuError, FmuFederate, FmuModel, InputError, Mapping, MappingError, NotCoSimulation, StepFailed)
from hlacore.fmu.exchange import Input
from hlacore.fmu.federate import LOOKAHEAD_MARGIN
from hlacore.fmu.mapping import ENCODINGS
from hlacore.fmu.model import Variable

from support import ROBOT_FED, Federate, tick_until
from support.fmus import FMU_SOURCES, build_fmu, build_python_fmu

F64 = omt.HLAfloat64BE
H = 0.1
STEPS = 20


@pytest.fixture(scope="session")
def lag_fmu(tmp_path_factory: pytest.TempPathFactory) -> pathlib.Path:
    """The first-order lag of tests/data/fmu/lag2 as an .fmu, compiled once per session."""
    (tmp_path_factory.getbasetemp() / "fmus").mkdir(exist_ok=True)
    return build_fmu("lag2", tmp_path_factory.getbasetemp() / "fmus")


@pytest.fixture(params=["lag2", "lag3"])
def any_lag(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> pathlib.Path:
    """The lag as an FMI 2 FMU (tests/data/fmu/lag2) and as an FMI 3 one (lag3), the same model."""
    return build_fmu(request.param, tmp_path_factory.getbasetemp() / "fmus")


@pytest.fixture
def no_leftovers(tmp_path: pathlib.Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[pathlib.Path]:
    """Temporary files go to a directory of the test's, which must be empty again at the end."""
    scratch = tmp_path / "scratch"
    scratch.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(scratch))
    yield scratch
    assert list(scratch.iterdir()) == [], "the FMU's unpacked files were left behind"


@pytest.fixture
def fmu_federation(gateway_address: str, lag_fmu: pathlib.Path, tmp_path: pathlib.Path) -> Iterator[str]:
    """FmuFed, created from the FOM the default mapping of the lag writes (class Lag, attributes u and y)."""
    fed = tmp_path / "lag.fed"
    fed.write_text(Mapping.by_name(FmuModel(lag_fmu)).fed("FmuFed"))
    creator = rti.RTIAmbassador(gateway_address)
    creator.createFederationExecution("FmuFed", str(fed))
    yield gateway_address
    creator.destroyFederationExecution("FmuFed")  # raises FederatesCurrentlyJoined if one was left joined


@pytest.fixture(scope="session")
def gain_fmu(tmp_path_factory: pytest.TempPathFactory) -> pathlib.Path:
    """The gain of tests/data/fmu/gain as a Python FMU, built by pythonfmu once per session."""
    (tmp_path_factory.getbasetemp() / "fmus").mkdir(exist_ok=True)
    return build_python_fmu("gain", tmp_path_factory.getbasetemp() / "fmus")


def signal(k: int) -> float:
    """The input u at the k-th grid point t = k h: a sine, so every step sees a new value."""
    return 1.0 + math.sin(3.0 * k * H)


@contextlib.contextmanager
def running(*federates: FmuFederate, stop_time: float = STEPS * H) -> Iterator[list[BaseException]]:
    """Each federate's ``run(stop_time)`` on a thread of its own while the block runs; the threads are joined
    at its end (they must have ended by then); yields the list of what the runs raised, complete after it."""
    failures: list[BaseException] = []

    def run(federate: FmuFederate) -> None:
        try:
            federate.run(stop_time)
        except BaseException as error:  # reported by the caller
            failures.append(error)

    threads = [threading.Thread(target=run, args=(federate,)) for federate in federates]
    for thread in threads:
        thread.start()
    try:
        yield failures
    finally:
        for thread in threads:
            thread.join(timeout=30.0)
    assert not any(thread.is_alive() for thread in threads)


def run_beside(federate: FmuFederate, feeder: Federate, send: Callable[[int], object]) -> list[BaseException]:
    """Run ``federate`` to STEPS h on a thread while ``feeder`` calls ``send(k)`` (to send stamped k h) and
    advances to k h, for k = 1 .. STEPS - 1 (and advances to STEPS h); what the run raised."""
    with running(federate) as failures:
        for k in range(1, STEPS + 1):
            if k < STEPS:
                send(k)
            assert feeder.rtia.advance_to(k * H, timeout=20.0) == pytest.approx(k * H)
    return failures


def test_against_a_feeder_gives_fmpys_trajectory(fmu_federation: str, any_lag: pathlib.Path,
                                                  no_leftovers: pathlib.Path) -> None:
    """A feeder federate sends u(t_k) stamped t_k; the FMU's outputs, recorded and as the feeder reflects them,
    equal fmpy.simulate_fmu's on the same input sampled at the same grid (tau set as a start value); FMI 2 and 3."""
    lag_fmu = any_lag
    feeder = Federate(fmu_federation, "feeder", federation="FmuFed")
    try:
        feeder.enable_time(lookahead=H * (1 - LOOKAHEAD_MARGIN))  # k H is always allowed, as for the FMU
        lag = feeder.rtia.getObjectClassHandle("Lag")
        u, y = (feeder.rtia.getAttributeHandle(name, lag) for name in ("u", "y"))
        feeder.rtia.publishObjectClass(lag, [u])
        feeder.rtia.subscribeObjectClassAttributes(lag, [y])
        source = feeder.rtia.registerObjectInstance(lag, "source")

        federate = FmuFederate(lag_fmu, "FmuFed", step_size=H, address=fmu_federation,
                               start_values={"u": signal(0), "tau": 0.5}, timeout=20.0)
        with federate:
            federate.join()
            failure = run_beside(federate, feeder, lambda k: feeder.rtia.updateAttributeValues(
                source, {u: F64.pack(signal(k))}, "feeder", k * H))
            assert not failure, failure
    finally:
        feeder.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)

    inputs = np.array([(k * H, signal(k)) for k in range(STEPS + 1)], dtype=[("time", float), ("u", float)])
    expected = fmpy.simulate_fmu(str(lag_fmu), stop_time=STEPS * H, output_interval=H, input=inputs,
                                 start_values={"tau": 0.5}, output=["y"])
    assert len(expected) == STEPS + 1
    times = [t for t, _ in federate.trajectory]
    assert times == pytest.approx(list(expected["time"]), abs=1e-12)
    assert [v["y"] for _, v in federate.trajectory] == pytest.approx(list(expected["y"]), rel=1e-12, abs=1e-15)
    reflected = [(args[5], F64.unpack(args[1][y])[0]) for args in feeder.amb.named("reflectAttributeValues")]
    assert [t for t, _ in reflected] == pytest.approx(list(expected["time"][1:]))
    assert [v for _, v in reflected] == pytest.approx(list(expected["y"][1:]), rel=1e-12, abs=1e-15)
    assert max(expected["y"]) > 1.0  # the input moved it: the comparison is not of two constant runs


def test_inputs_from_interactions(gateway_address: str, lag_fmu: pathlib.Path, tmp_path: pathlib.Path) -> None:
    """u mapped to a parameter of an interaction: the feeder sends SetU(value) stamped t_k, and the run equals
    fmpy.simulate_fmu on the same input, as with attributes; the FOM written declares the interaction."""
    mapping = tmp_path / "mapping.toml"
    mapping.write_text('[inputs]\nu = { parameter = "SetU.value" }\n[outputs]\ny = "Lag.y"\n')
    fed = tmp_path / "lag.fed"
    fed.write_text(Mapping.load(mapping, FmuModel(lag_fmu)).fed("FmuFed"))
    assert "(class SetU reliable timestamp\n    (parameter value))" in fed.read_text()
    rti.RTIAmbassador(gateway_address).createFederationExecution("FmuFed", str(fed))
    feeder = Federate(gateway_address, "feeder", federation="FmuFed")
    try:
        feeder.enable_time(lookahead=H * (1 - LOOKAHEAD_MARGIN))
        set_u = feeder.rtia.getInteractionClassHandle("SetU")
        value = feeder.rtia.getParameterHandle("value", set_u)
        feeder.rtia.publishInteractionClass(set_u)
        with FmuFederate(lag_fmu, "FmuFed", step_size=H, address=gateway_address, mapping=mapping,
                         start_values={"u": signal(0)}, timeout=20.0) as federate:
            federate.join()
            failure = run_beside(federate, feeder, lambda k: feeder.rtia.sendInteraction(
                set_u, {value: F64.pack(signal(k))}, "feeder", k * H))
            assert not failure, failure
    finally:
        feeder.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        rti.RTIAmbassador(gateway_address).destroyFederationExecution("FmuFed")
    inputs = np.array([(k * H, signal(k)) for k in range(STEPS + 1)], dtype=[("time", float), ("u", float)])
    expected = fmpy.simulate_fmu(str(lag_fmu), stop_time=STEPS * H, output_interval=H, input=inputs, output=["y"])
    assert [v["y"] for _, v in federate.trajectory] == pytest.approx(list(expected["y"]), rel=1e-12, abs=1e-15)
    assert max(expected["y"]) > 1.0



ARRAY_MAPPING = """[inputs]
u = { attribute = "Src.v", element = 1, instance = "good" }
[outputs]
y = { parameter = "Report.y" }
[constants]
"Report.who" = "lag"
"""


@pytest.fixture
def array_federation(gateway_address: str, lag_fmu: pathlib.Path, tmp_path: pathlib.Path) -> Iterator[Federate]:
    """ArrayFed from ARRAY_MAPPING's FOM, and a feeder that publishes Src.v, registers the instances "good" and
    "other", and subscribes to Report; the federation is destroyed at the end (nobody may be left joined)."""
    mapping = tmp_path / "mapping.toml"
    mapping.write_text(ARRAY_MAPPING)
    fed = tmp_path / "array.fed"
    fed.write_text(Mapping.load(mapping, FmuModel(lag_fmu)).fed("ArrayFed"))
    rti.RTIAmbassador(gateway_address).createFederationExecution("ArrayFed", str(fed))
    feeder = Federate(gateway_address, "feeder", federation="ArrayFed")
    try:
        feeder.enable_time(lookahead=H * (1 - LOOKAHEAD_MARGIN))
        src = feeder.rtia.getObjectClassHandle("Src")
        feeder.rtia.publishObjectClass(src, [feeder.rtia.getAttributeHandle("v", src)])
        feeder.rtia.subscribeInteractionClass(feeder.rtia.getInteractionClassHandle("Report"))
        for name in ("good", "other"):
            feeder.rtia.registerObjectInstance(src, name)
        yield feeder
    finally:
        feeder.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        rti.RTIAmbassador(gateway_address).destroyFederationExecution("ArrayFed")


def send_array(feeder: Federate, instance: str, values: list[float], k: int) -> None:
    """Update Src.v of ``instance`` to ``values`` (an HLAfixedArray of HLAfloat64BE), stamped k h."""
    src = feeder.rtia.getObjectClassHandle("Src")
    feeder.rtia.updateAttributeValues(feeder.rtia.getObjectInstanceHandle(instance),
                                      {feeder.rtia.getAttributeHandle("v", src): b"".join(map(F64.pack, values))},
                                      "feeder", k * H)


def test_array_elements_one_instance_and_outputs_as_interactions(gateway_address: str, array_federation: Federate,
                                                                 lag_fmu: pathlib.Path,
                                                                 tmp_path: pathlib.Path) -> None:
    """u is element 1 of the array Src.v of the instance "good" only (the instance "other" sends 9s at the
    same times, after it); y goes out as Report(y, who = "lag"), a constant: the run and the interactions the
    feeder receives equal fmpy.simulate_fmu's on good's element 1."""
    feeder = array_federation
    (tmp_path / "mapping.toml").write_text(ARRAY_MAPPING)

    def send(k: int) -> None:
        send_array(feeder, "good", [-1.0, signal(k), -2.0], k)
        send_array(feeder, "other", [9.0, 9.0, 9.0], k)

    with FmuFederate(lag_fmu, "ArrayFed", step_size=H, address=gateway_address,
                     mapping=tmp_path / "mapping.toml", start_values={"u": signal(0)}, timeout=20.0) as federate:
        federate.join()
        assert not run_beside(federate, feeder, send)
    inputs = np.array([(k * H, signal(k)) for k in range(STEPS + 1)], dtype=[("time", float), ("u", float)])
    expected = fmpy.simulate_fmu(str(lag_fmu), stop_time=STEPS * H, output_interval=H, input=inputs, output=["y"])
    assert [v["y"] for _, v in federate.trajectory] == pytest.approx(list(expected["y"]), rel=1e-12, abs=1e-15)
    report = feeder.rtia.getInteractionClassHandle("Report")
    y, who = (feeder.rtia.getParameterHandle(name, report) for name in ("y", "who"))
    received = [(args[5], args[1]) for args in feeder.amb.named("receiveInteraction") if args[0] == report]
    assert [t for t, _ in received] == pytest.approx([k * H for k in range(1, STEPS + 1)])
    assert [F64.unpack(p[y])[0] for _, p in received] == pytest.approx(list(expected["y"][1:]), rel=1e-12)
    assert {omt.HLAASCIIstring.unpack(p[who])[0] for _, p in received} == {b"lag"}


def test_a_value_of_the_wrong_size_resigns_with_an_input_error(gateway_address: str, array_federation: Federate,
                                                               lag_fmu: pathlib.Path, tmp_path: pathlib.Path) -> None:
    """An array too short for the element mapped (one float where element 1 is read) fails the step that would
    use it with InputError naming the input and the sizes, after resigning: the federation can be destroyed."""
    feeder = array_federation
    (tmp_path / "mapping.toml").write_text(ARRAY_MAPPING)
    with FmuFederate(lag_fmu, "ArrayFed", step_size=H, address=gateway_address,
                     mapping=tmp_path / "mapping.toml", timeout=20.0) as federate:
        federate.join()
        failure = run_beside(federate, feeder, lambda k: send_array(feeder, "good", [1.0] if k == 3 else [0, 1, 2], k))
    assert [type(error) for error in failure] == [InputError]
    assert "u: instance 'good' sent 8 bytes, not an array of HLAfloat64BE with an element 1" in str(failure[0])
    assert federate.time == pytest.approx(3 * H)


TYPED = {"n": omt.HLAinteger32BE, "flag": omt.HLAboolean, "word": omt.HLAunicodeString,
         "twice": omt.HLAinteger32BE, "negated": omt.HLAboolean, "shout": omt.HLAunicodeString}


@contextlib.contextmanager
def feeding(gateway_address: str, fmu: pathlib.Path, directory: pathlib.Path
            ) -> Iterator[tuple[Federate, dict[str, Any], Any]]:
    """A federation from the FMU's by-name FOM, and a feeder that publishes the FMU's inputs on its instance
    "source" and subscribes to the outputs: (the feeder, the attribute handles by variable name, the instance).
    The federation is destroyed at the end (nobody may be left joined)."""
    mapping = Mapping.by_name(FmuModel(fmu))
    (cls,) = {endpoint.object_class for endpoint in [*mapping.inputs.values(), *mapping.outputs.values()]}
    (directory / "by-name.fed").write_text(mapping.fed("FeedFed"))
    rti.RTIAmbassador(gateway_address).createFederationExecution("FeedFed", str(directory / "by-name.fed"))
    feeder = Federate(gateway_address, "feeder", federation="FeedFed")
    try:
        feeder.enable_time(lookahead=H * (1 - LOOKAHEAD_MARGIN))
        handle = feeder.rtia.getObjectClassHandle(cls)
        handles = {name: feeder.rtia.getAttributeHandle(name, handle) for name in [*mapping.inputs, *mapping.outputs]}
        feeder.rtia.publishObjectClass(handle, [handles[name] for name in mapping.inputs])
        feeder.rtia.subscribeObjectClassAttributes(handle, [handles[name] for name in mapping.outputs])
        yield feeder, handles, feeder.rtia.registerObjectInstance(handle, "source")
    finally:
        feeder.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        rti.RTIAmbassador(gateway_address).destroyFederationExecution("FeedFed")


@pytest.fixture
def typed_federation(gateway_address: str, tmp_path: pathlib.Path, tmp_path_factory: pytest.TempPathFactory
                     ) -> Iterator[tuple[pathlib.Path, Federate, dict[str, Any], Any]]:
    """The Python FMU of tests/data/fmu/typed (an Integer, a Boolean and a String input and output) fed by name:
    (the FMU, the feeder, the attribute handles by name, the instance)."""
    typed_fmu = build_python_fmu("typed", tmp_path_factory.getbasetemp() / "fmus")
    with feeding(gateway_address, typed_fmu, tmp_path) as fed:
        yield (typed_fmu, *fed)


def test_integers_booleans_and_strings_travel(gateway_address: str, typed_federation: Any) -> None:
    """Mapped by name, the feeder sends n = k, flag = k odd and word = "w<k>" stamped k h (HLAinteger32BE,
    HLAboolean, HLAunicodeString) and reflects twice = 2 n, negated = not flag and shout = "W<k>!" of the step
    before, stamped (k + 1) h."""
    typed_fmu, feeder, handles, source = typed_federation

    def send(k: int) -> None:
        values = {"n": k, "flag": k % 2 == 1, "word": f"w{k}"}
        feeder.rtia.updateAttributeValues(source, {handles[name]: TYPED[name].pack(value)
                                                   for name, value in values.items()}, "feeder", k * H)

    with FmuFederate(typed_fmu, "FeedFed", step_size=H, address=gateway_address, timeout=20.0,
                     start_values={"n": 0, "flag": False, "word": "w0"}) as federate:
        federate.join()
        assert not run_beside(federate, feeder, send)
    reflected = [(args[5], {name: TYPED[name].unpack(args[1][handles[name]])[0]
                            for name in ("twice", "negated", "shout")})
                 for args in feeder.amb.named("reflectAttributeValues")]
    assert [t for t, _ in reflected] == pytest.approx([k * H for k in range(1, STEPS + 1)])
    assert [v for _, v in reflected] == [{"twice": 2 * (k - 1), "negated": (k - 1) % 2 == 0, "shout": f"W{k - 1}!"}
                                         for k in range(1, STEPS + 1)]


def test_a_string_that_is_not_one_unicode_string_is_an_input_error(gateway_address: str,
                                                                   typed_federation: Any) -> None:
    """Five UTF-16 characters announced, one sent: the step that would set the word raises InputError, after
    resigning. (Nor can a String be an array's element: its size varies.)"""
    typed_fmu, feeder, handles, source = typed_federation
    with pytest.raises(MappingError, match="word: a String is no array element"):
        Mapping({"word": Endpoint("Typed", "word", element=0)}).check(FmuModel(typed_fmu))
    with FmuFederate(typed_fmu, "FeedFed", step_size=H, address=gateway_address, timeout=20.0) as federate:
        federate.join()
        failures = run_beside(federate, feeder, lambda k: feeder.rtia.updateAttributeValues(
            source, {handles["word"]: b"\x00\x00\x00\x05ab" if k == 2 else TYPED["word"].pack("ok")}, "feeder",
            k * H))
    assert [type(error) for error in failures] == [InputError]
    assert "word: instance 'source' sent 6 bytes, not one HLAunicodeString" in str(failures[0])


#: FMI 3's other types: each input of tests/data/fmu/typed3 (its output is <type>_out), its encoding and its
#: value at step k.
TYPED3: dict[str, tuple[Any, Callable[[int], Any]]] = {
    "float32": (omt.HLAfloat32BE, lambda k: k + 0.5), "int8": (omt.HLAinteger16BE, lambda k: -k),
    "uint8": (omt.HLAoctet, lambda k: 200 + k), "int16": (omt.HLAinteger16BE, lambda k: -1000 * k),
    "uint16": (omt.Unsignedinteger16BE, lambda k: 60000 + k), "uint32": (omt.Unsignedinteger32BE, lambda k: 4 * 10**9 + k),
    "int64": (omt.HLAinteger64BE, lambda k: -2**62 + k), "uint64": (omt.Unsignedinteger64BE, lambda k: 2**64 - 1 - k),
    "string": (omt.HLAunicodeString, lambda k: f"é{k}"), "binary": (omt.HLAopaqueData, lambda k: bytes([k, 0, 255])),
    "gear": (omt.HLAinteger32BE, lambda k: (-1, 0, 1)[k % 3])}


def test_fmi3s_other_types_travel(gateway_address: str, tmp_path: pathlib.Path,
                                  tmp_path_factory: pytest.TempPathFactory) -> None:
    """An FMI 3 FMU in C (tests/data/fmu/typed3) copies an input of each of Float32, Int8, UInt8, Int16, UInt16,
    UInt32, Int64, UInt64, String, Binary and an Enumeration to an output at each step: mapped by name, each value
    the feeder sends at k h (HLAfloat32BE, HLAinteger16BE for the Int8, HLAoctet, HLAinteger16BE,
    Unsignedinteger16BE/32BE, HLAinteger64BE, Unsignedinteger64BE, HLAunicodeString, HLAopaqueData,
    HLAinteger32BE) comes back at (k + 1) h, extremes included; an Int8 beyond its range is an InputError."""
    typed3 = build_fmu("typed3", tmp_path_factory.getbasetemp() / "fmus")
    with feeding(gateway_address, typed3, tmp_path) as (feeder, handles, source):
        def send(k: int) -> None:
            feeder.rtia.updateAttributeValues(source, {handles[f"{name}_in"]: codec.pack(value(k))
                                                       for name, (codec, value) in TYPED3.items()}, "feeder", k * H)

        start = {f"{name}_in": value(0) for name, (_, value) in TYPED3.items()}
        with FmuFederate(typed3, "FeedFed", step_size=H, address=gateway_address, timeout=20.0,
                         start_values=start) as federate:
            federate.join()
            assert not run_beside(federate, feeder, send)
        reflected = [(args[5], {name: codec.unpack(args[1][handles[f"{name}_out"]])[0]
                                for name, (codec, _) in TYPED3.items()})
                     for args in feeder.amb.named("reflectAttributeValues")]
        assert [t for t, _ in reflected] == pytest.approx([k * H for k in range(1, STEPS + 1)])
        assert [v for _, v in reflected] == [
            {name: bytes([value(k - 1)]) if name == "uint8" else value(k - 1) for name, (_, value) in TYPED3.items()}
            for k in range(1, STEPS + 1)]
    with feeding(gateway_address, typed3, tmp_path) as (feeder, handles, source):
        with FmuFederate(typed3, "FeedFed", step_size=H, address=gateway_address, timeout=20.0) as federate:
            federate.join()
            failures = run_beside(federate, feeder, lambda k: feeder.rtia.updateAttributeValues(
                source, {handles["int8_in"]: omt.HLAinteger16BE.pack(300 if k == 2 else k)}, "feeder", k * H))
    assert [type(error) for error in failures] == [InputError]
    assert "int8_in: instance 'source' sent 300, beyond its type's (-128, 127)" in str(failures[0])


#: tests/data/fmu/gear2's variables and their encodings (Gear: Reverse = -1, Neutral = 0, Drive = 1).
GEARBOX = {"gear": omt.HLAinteger32BE, "throttle": F64, "speed": F64, "engaged": omt.HLAinteger32BE,
           "shifts": omt.HLAinteger32BE}


@pytest.fixture(scope="session")
def gearbox(tmp_path_factory: pytest.TempPathFactory) -> pathlib.Path:
    """The gearbox of tests/data/fmu/gear2 (FMI 2, on hlacore's C skeleton) as an .fmu, compiled once per session."""
    return build_fmu("gear2", tmp_path_factory.getbasetemp() / "fmus")


def gear(k: int) -> int:
    """The gear the feeder sends at step k: Drive, Drive, Reverse, Neutral, ... (a change at every step but one
    in four)."""
    return (1, 1, -1, 0)[k % 4]


def test_enumerations_travel(gateway_address: str, tmp_path: pathlib.Path, gearbox: pathlib.Path) -> None:
    """An FMI 2 FMU on hlacore's C skeleton (tests/data/fmu/gear2) with an Enumeration input and output and an
    Integer output: the start value is given by the item's name ("Drive"); the gear the feeder sends at k h as
    HLAinteger32BE comes back engaged at (k + 1) h, with speed = gear * throttle and the count of shifts."""
    with feeding(gateway_address, gearbox, tmp_path) as (feeder, handles, source):
        def send(k: int) -> None:
            feeder.rtia.updateAttributeValues(source, {handles["gear"]: GEARBOX["gear"].pack(gear(k)),
                                                       handles["throttle"]: F64.pack(k)}, "feeder", k * H)

        with FmuFederate(gearbox, "FeedFed", step_size=H, address=gateway_address, timeout=20.0,
                         start_values={"gear": "Drive", "throttle": 0.0}) as federate:
            federate.join()
            assert not run_beside(federate, feeder, send)
        reflected = [{name: GEARBOX[name].unpack(args[1][handles[name]])[0] for name in ("speed", "engaged", "shifts")}
                     for args in feeder.amb.named("reflectAttributeValues")]
    assert [args[5] for args in feeder.amb.named("reflectAttributeValues")] == pytest.approx(
        [k * H for k in range(1, STEPS + 1)])
    assert reflected == [{"speed": gear(k) * k, "engaged": gear(k), "shifts": sum(gear(j) != gear(j - 1)
                                                                                  for j in range(1, k + 1))}
                         for k in range(STEPS)]


def test_an_enumeration_beyond_its_items_is_refused(gateway_address: str, tmp_path: pathlib.Path,
                                                    gearbox: pathlib.Path) -> None:
    """An item beyond the 32 bits it travels in (FMI 3's enumerations are 64-bit) and a start value no item has
    (by name or value) are MappingErrors before joining; a received value no item has is an InputError, and an
    output no item has (the gearbox jams on a negative throttle) a StepFailed, each by the step concerned, after
    resigning."""
    model = FmuModel(gearbox)
    model.variables["gear"] = dataclasses.replace(model.variables["gear"], items=(("Far", 2**40),))
    with pytest.raises(MappingError, match="gear: an item of its Enumeration is beyond HLAinteger32BE"):
        Mapping.by_name(model).check(model)
    for start in ("Fifth", 5):
        with pytest.raises(MappingError, match=rf"gear = {start!r}: not one of its items \(Reverse = -1, "
                                               r"Neutral = 0, Drive = 1\)"):
            FmuFederate(gearbox, "FeedFed", step_size=H, start_values={"gear": start})
    for field, bad, error, message in [
            ("gear", 5, InputError, "gear: instance 'source' sent 5, not one of its items (Reverse = -1, "
                                    "Neutral = 0, Drive = 1)"),
            ("throttle", -1.0, StepFailed, f"output engaged = 2 at t = {3 * H:g}, not one of its items")]:
        with feeding(gateway_address, gearbox, tmp_path) as (feeder, handles, source):
            def send(k: int) -> None:
                values = {"gear": 1, "throttle": 1.0, **({field: bad} if k == 2 else {})}
                feeder.rtia.updateAttributeValues(source, {handles[name]: GEARBOX[name].pack(value)
                                                           for name, value in values.items()}, "feeder", k * H)

            with FmuFederate(gearbox, "FeedFed", step_size=H, address=gateway_address, timeout=20.0) as federate:
                federate.join()
                failures = run_beside(federate, feeder, send)
        assert [type(failure) for failure in failures] == [error]
        assert message in str(failures[0])


@settings(max_examples=300, deadline=None)
@given(kind=st.sampled_from(sorted(ENCODINGS)), element=st.sampled_from([None, 0, 2]), data=st.binary(max_size=40))
def test_any_bytes_received_decode_to_a_value_the_input_takes_or_to_an_input_error(kind: str, element: Any,
                                                                                   data: bytes) -> None:
    """The decoder of what other federates send (exchange.Input), fuzzed: for each type that travels, whole or as
    an element, any bytes give a value the variable takes (Variable.refusal) or an InputError, nothing else."""
    variable = Variable("v", 0, kind, "input", (("A", -1), ("B", 7)) if kind == "Enumeration" else ())
    received = Input(variable, None if ENCODINGS[kind].fixed_size is None else element, None)
    try:
        value = received.decode(data, "fuzz")
    except InputError as error:
        assert str(error).startswith("v: fuzz sent ")
    else:
        assert variable.refusal(value) is None


def test_command_line_writes_the_fom_and_runs(inprocess_gateway: hlacore.Gateway, any_lag: pathlib.Path,
                                              tmp_path: pathlib.Path) -> None:
    """--write-fom writes the by-name FOM; the command then creates the federation from it, runs alone to the
    stop time with a parameter from --start, and its CSV is fmpy's run of the same start values; FMI 2 and 3.
    --alone does the same with no gateway to give (an in-process one, the FOM from the mapping), and not with
    --address."""
    lag_fmu = any_lag
    fed, table = tmp_path / "lag.fed", tmp_path / "y.csv"
    command = [sys.executable, "-m", "hlacore.fmu", str(lag_fmu), "--federation", "CliFed"]
    done = subprocess.run(command + ["--write-fom", str(fed)], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert "(class Lag\n    (attribute u reliable timestamp)\n    (attribute y reliable timestamp))" in fed.read_text()
    done = subprocess.run(command + ["--fed", str(fed), "--address", str(inprocess_gateway.address),
                                     "--step-size", "0.25", "--stop-time", "1", "--start", "u=2", "--start",
                                     "tau=0.5", "--csv", str(table)], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert "Lag: 4 steps to t = 1" in done.stdout
    rows = [line.split(",") for line in table.read_text().split()]
    expected = fmpy.simulate_fmu(str(lag_fmu), stop_time=1.0, output_interval=0.25,
                                 start_values={"u": 2.0, "tau": 0.5}, output=["y"])
    assert rows[0] == ["time", "y"]
    assert [float(r[1]) for r in rows[1:]] == pytest.approx(list(expected["y"]), rel=1e-12)
    rti.RTIAmbassador(str(inprocess_gateway.address)).destroyFederationExecution("CliFed")  # nobody left joined
    alone = tmp_path / "alone.csv"
    done = subprocess.run(command + ["--alone", "--step-size", "0.25", "--stop-time", "1", "--start", "u=2",
                                     "--start", "tau=0.5", "--csv", str(alone)], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 0, done.stderr
    assert alone.read_text() == table.read_text()
    done = subprocess.run(command + ["--alone", "--address", "127.0.0.1:60400"], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 2 and "--address: not allowed with argument --alone" in done.stderr, done.stderr


def _rezip(source: pathlib.Path, target: pathlib.Path, description: str | None = None,
           binaries: bool = True) -> pathlib.Path:
    with zipfile.ZipFile(source) as old, zipfile.ZipFile(target, "w") as new:
        for item in old.namelist():
            if item == "modelDescription.xml":
                new.writestr(item, description if description is not None else old.read(item))
            elif binaries:
                new.writestr(item, old.read(item))
    return target


def test_bad_fmus_are_refused_before_anything_runs(lag_fmu: pathlib.Path, tmp_path: pathlib.Path) -> None:
    """A missing file, one that is not a zip, a zip without a model description, a model-exchange-only FMU and
    one without this platform's binary: each a clear error naming the file, before joining."""
    description = (FMU_SOURCES / "lag2" / "modelDescription.xml").read_text()
    corrupt = tmp_path / "corrupt.fmu"
    corrupt.write_bytes(b"\x00not a zip" * 10)
    empty = tmp_path / "empty.fmu"
    with zipfile.ZipFile(empty, "w") as archive:
        archive.writestr("readme.txt", "no model description")
    exchange_only = _rezip(lag_fmu, tmp_path / "me.fmu", description.replace(
        '<CoSimulation modelIdentifier="lag"', '<ModelExchange modelIdentifier="lag"'))
    no_binary = _rezip(lag_fmu, tmp_path / "nobin.fmu", binaries=False)
    cases: list[tuple[pathlib.Path, type[Exception], str]] = [
        (tmp_path / "absent.fmu", FmuError, "absent.fmu: no such FMU"),
        (corrupt, FmuError, "corrupt.fmu: not an FMU"),
        (empty, FmuError, "empty.fmu: unreadable model description"),
        (exchange_only, NotCoSimulation, "me.fmu: exports model exchange only"),
        (no_binary, FmuError, r"nobin.fmu: no binary for this platform \(binaries/linux64/lag.so is missing\)"),
    ]
    for path, error, message in cases:
        with pytest.raises(error, match=message):
            FmuFederate(path, "NoFed", step_size=H, address="unused:1")
    done = subprocess.run([sys.executable, "-m", "hlacore.fmu", str(exchange_only)], capture_output=True,
                          text=True, timeout=60)
    assert done.returncode == 2 and "error: " in done.stderr and "model exchange only" in done.stderr, done.stderr


def test_bad_mappings_and_start_values_are_refused(lag_fmu: pathlib.Path, tmp_path: pathlib.Path) -> None:
    """An unknown variable, an output mapped as an input, a malformed endpoint, an output array with a gap, a
    constant of no output class or of no HLA type, a start value of the wrong type or for no variable: each a
    MappingError before joining."""
    cases = {'[inputs]\nspeed = "Lag.speed"\n': "has no variable 'speed'",
             '[inputs]\ny = "Lag.y"\n': "its causality is output, not input",
             '[outputs]\ny = "y"\n': "'y' is not ObjectClass.attribute",
             '[outputs]\ny = { attribute = "Lag.y", element = 1 }\n': "needs each of its elements 0..n-1 once",
             '[outputs]\ny = { attribute = "Lag.y", instance = "a" }\n': "outputs go to this federate's own",
             '[inputs]\nu = { attribute = "Lag.u", element = -1 }\n': "an array index, 0 or more",
             '[outputs]\ny = "Lag.y"\n[constants]\n"Report.who" = "lag"\n': "Report is no class the outputs",
             '[outputs]\ny = "Lag.y"\n[constants]\n"Lag.who" = [1]\n': "a constant is a string, a number",
             '[inputs]\nu = { param = "SetU.value" }\n': "expected",
             '[extra]\n': r"unknown table\(s\) \['extra'\]"}
    for text, message in cases.items():
        mapping = tmp_path / "mapping.toml"
        mapping.write_text(text)
        with pytest.raises(MappingError, match=message):
            FmuFederate(lag_fmu, "NoFed", step_size=H, mapping=mapping)
    with pytest.raises(MappingError, match="tau = True: tau is of type Real"):
        FmuFederate(lag_fmu, "NoFed", step_size=H, start_values={"tau": True})
    with pytest.raises(MappingError, match="has no variable 'gain'"):
        FmuFederate(lag_fmu, "NoFed", step_size=H, start_values={"gain": 1.0})


@pytest.mark.parametrize("parameter, message", [("fail_time", "doStep at t = 0.3 failed"),
                                                ("nan_time", "output y = nan at t = 0.4")])
def test_a_failing_step_resigns_cleanly(fmu_federation: str, lag_fmu: pathlib.Path, no_leftovers: pathlib.Path,
                                        parameter: str, message: str) -> None:
    """A doStep that fails, or leaves y NaN, raises StepFailed after resigning: the federation can be destroyed
    (the fixture does) and the unpacked FMU is gone."""
    federate = FmuFederate(lag_fmu, "FmuFed", step_size=H, address=fmu_federation,
                           start_values={parameter: 0.3 if parameter == "fail_time" else 0.35})
    federate.join()
    with pytest.raises(StepFailed, match=message):
        federate.run(1.0)
    assert federate.time == pytest.approx(0.3)
    with pytest.raises(rti.FederateNotExecutionMember):
        federate.rtia


def test_a_class_the_fom_lacks_resigns_before_running(gateway_address: str, lag_fmu: pathlib.Path,
                                                     no_leftovers: pathlib.Path) -> None:
    """Joined to a federation whose FOM has no class Lag, join() raises NameNotFound after resigning; the command
    says so and exits with status 1."""
    creator = rti.RTIAmbassador(gateway_address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    try:
        with pytest.raises(rti.NameNotFound):
            FmuFederate(lag_fmu, "TestFed", step_size=H, address=gateway_address).join()
        done = subprocess.run([sys.executable, "-m", "hlacore.fmu", str(lag_fmu), "--federation", "TestFed",
                               "--address", gateway_address, "--stop-time", "1"], capture_output=True, text=True,
                              timeout=60, env={**os.environ, "TMPDIR": str(no_leftovers)})
        assert done.returncode == 1 and "error: NameNotFound" in done.stderr, done.stderr
    finally:
        creator.destroyFederationExecution("TestFed")


def test_two_fmus_coupled_through_the_federation(inprocess_gateway: hlacore.Gateway, lag_fmu: pathlib.Path,
                                                 tmp_path: pathlib.Path, no_leftovers: pathlib.Path) -> None:
    """Two lags, each one's input the other's output, by mapping files: both trajectories are the coupled
    system stepped independently here (each step holds the other's output at its start, as the federation
    delivers it; at t = 0 the inputs are their start values)."""
    address = str(inprocess_gateway.address)
    (tmp_path / "a.toml").write_text('[inputs]\nu = "B.y"\n[outputs]\ny = "A.y"\n')
    (tmp_path / "b.toml").write_text('[inputs]\nu = "A.y"\n[outputs]\ny = "B.y"\n')
    fed = tmp_path / "coupled.fed"
    fed.write_text(Mapping(outputs={"a": Endpoint("A", "y"), "b": Endpoint("B", "y")}).fed("Coupled"))
    rti.RTIAmbassador(address).createFederationExecution("Coupled", str(fed))
    parameters = {"a": {"tau": 0.5, "x0": 1.0, "u": 0.0}, "b": {"tau": 2.0, "x0": 0.0, "u": 1.0}}
    federates = {name: FmuFederate(lag_fmu, "Coupled", step_size=H, name=name, address=address,
                                   mapping=tmp_path / f"{name}.toml", start_values=parameters[name], timeout=20.0)
                 for name in ("a", "b")}
    try:
        for federate in federates.values():
            federate.join()
        with running(*federates.values()) as failures:
            pass
        assert not failures, failures
    finally:
        for federate in federates.values():
            federate.close()
    rti.RTIAmbassador(address).destroyFederationExecution("Coupled")

    x = {"a": 1.0, "b": 0.0}
    u = {"a": 0.0, "b": 1.0}
    expected: dict[str, list[float]] = {"a": [x["a"]], "b": [x["b"]]}
    for _ in range(STEPS):
        x = {n: u[n] + (x[n] - u[n]) * math.exp(-H / parameters[n]["tau"]) for n in x}
        u = {"a": x["b"], "b": x["a"]}
        for n in x:
            expected[n].append(x[n])
    for name, federate in federates.items():
        assert [t for t, _ in federate.trajectory] == pytest.approx([k * H for k in range(STEPS + 1)])
        assert [v["y"] for _, v in federate.trajectory] == pytest.approx(expected[name], rel=1e-12)
    assert abs(expected["a"][-1] - expected["b"][-1]) < 0.2  # they pulled each other together


def test_save_then_restore_mid_run_continues_to_the_same_end(fmu_federation: str, any_lag: pathlib.Path,
                                                            tmp_path: pathlib.Path) -> None:
    """A federation save at t = 0.5 keeps the FMU's serialised state; after the run reached 1.0, a restore
    rewinds the federate and the FMU to 0.5 and the run continues to the same trajectory and end value; FMI 2
    and 3."""
    lag_fmu = any_lag
    controller = Federate(fmu_federation, "controller", federation="FmuFed")
    try:
        federate = FmuFederate(lag_fmu, "FmuFed", step_size=H, address=fmu_federation, timeout=20.0,
                               start_values={"u": 2.0}, save_dir=tmp_path / "saves")
        with federate:
            federate.join()
            controller.rtia.requestFederationSave("half", 0.5)
            tick_until(lambda: controller.amb.named("initiateFederateSave"), controller.rtia)
            controller.rtia.federateSaveComplete()
            first = list(federate.run(1.0))
            tick_until(lambda: controller.amb.named("federationSaved"), controller.rtia)
            assert federate.state_file("half").is_file() and federate.saved == ["half"] and not federate.save_errors

            controller.rtia.requestFederationRestore("half")
            tick_until(lambda: controller.amb.named("initiateFederateRestore"), controller.rtia)
            controller.rtia.federateRestoreComplete()
            tick_until(lambda: federate.restored == ["half"], federate.rtia)  # initiateFederateRestore delivered
            federate.settle()  # until federationRestored: the FMU is back at 0.5
            assert federate.time == pytest.approx(0.5) and federate.rtia.queryFederateTime() == pytest.approx(0.5)
            assert len(federate.trajectory) == 6
            again = federate.run(1.0)
            tick_until(lambda: controller.amb.named("federationRestored"), controller.rtia)
    finally:
        controller.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
    assert [t for t, _ in again] == pytest.approx([t for t, _ in first])
    assert [v["y"] for _, v in again] == [v["y"] for _, v in first]
    assert first[-1][1]["y"] == pytest.approx(2.0 * (1 - math.exp(-1.0)))


def test_a_save_and_a_restore_while_the_fmu_waits_for_its_grant(fmu_federation: str, lag_fmu: pathlib.Path,
                                                                tmp_path: pathlib.Path) -> None:
    """A regulating controller holds the FMU back: the save comes while the FMU waits for its grant of 0.5
    (the step to 0.5 done and sent), the restore while it waits for 1.0. The restore ends that wait at once,
    the FMU resumes at 0.4 with the step to 0.5 still to be granted, and the run ends on the lag's exact
    trajectory, each grid time once."""
    controller = Federate(fmu_federation, "controller", federation="FmuFed")
    controller.enable_time(lookahead=H * (1 - LOOKAHEAD_MARGIN), constrained=False)
    try:
        with FmuFederate(lag_fmu, "FmuFed", step_size=H, address=fmu_federation, timeout=20.0,
                         start_values={"u": 2.0}, save_dir=tmp_path / "saves") as federate:
            federate.join()

            def waiting_at(time: float) -> None:  # the FMU granted time, its next step sent and its grant awaited
                tick_until(lambda: federate.time == pytest.approx(time) and federate.pending is not None,
                           controller.rtia)

            with running(federate, stop_time=2.0) as failures:
                controller.rtia.advance_to(0.4, timeout=20.0)  # the FMU may now reach 0.4, not 0.5
                waiting_at(0.4)
                controller.rtia.requestFederationSave("mid")
                tick_until(lambda: controller.amb.named("initiateFederateSave"), controller.rtia)
                controller.rtia.federateSaveComplete()
                tick_until(lambda: controller.amb.named("federationSaved"), controller.rtia)
                assert federate.saved == ["mid"]
                controller.rtia.advance_to(0.9, timeout=20.0)
                waiting_at(0.9)
                controller.rtia.requestFederationRestore("mid")
                tick_until(lambda: controller.amb.named("initiateFederateRestore"), controller.rtia)
                controller.rtia.federateRestoreComplete()
                tick_until(lambda: controller.amb.named("federationRestored"), controller.rtia)
                assert controller.rtia.queryFederateTime() == pytest.approx(0.4)
                for k in range(5, 21):
                    controller.rtia.advance_to(k * H, timeout=20.0)
            assert not failures, failures
    finally:
        controller.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
    assert federate.restored == ["mid"] and not federate.save_errors
    assert [t for t, _ in federate.trajectory] == pytest.approx([k * H for k in range(21)])
    assert [v["y"] for _, v in federate.trajectory] == pytest.approx(
        [2.0 * (1 - math.exp(-k * H)) for k in range(21)], rel=1e-12, abs=1e-15)


def test_an_fmu_that_cannot_save_makes_the_save_fail_clearly(fmu_federation: str, lag_fmu: pathlib.Path,
                                                             tmp_path: pathlib.Path) -> None:
    """An FMU whose model description says it cannot get and set its state answers the save with
    federateSaveNotComplete: everyone gets federationNotSaved, the reason is kept, the run goes on."""
    description = (FMU_SOURCES / "lag2" / "modelDescription.xml").read_text()
    stateless = _rezip(lag_fmu, tmp_path / "stateless.fmu", description.replace(
        'canGetAndSetFMUstate="true"', 'canGetAndSetFMUstate="false"'))
    controller = Federate(fmu_federation, "controller", federation="FmuFed")
    try:
        with FmuFederate(stateless, "FmuFed", step_size=H, address=fmu_federation, timeout=20.0,
                         save_dir=tmp_path / "saves") as federate:
            federate.join()
            controller.rtia.requestFederationSave("half", 0.5)
            tick_until(lambda: controller.amb.named("initiateFederateSave"), controller.rtia)
            controller.rtia.federateSaveComplete()
            federate.run(1.0)
            tick_until(lambda: controller.amb.named("federationNotSaved"), controller.rtia)
            assert "cannot save its state" in federate.save_errors["half"]
            assert federate.time == pytest.approx(1.0)
    finally:
        controller.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)


def test_a_python_fmu_behind_a_c_fmu(inprocess_gateway: hlacore.Gateway, lag_fmu: pathlib.Path,
                                     gain_fmu: pathlib.Path, tmp_path: pathlib.Path) -> None:
    """A pythonfmu FMU (the gain, k = 3) reads the lag's output through the federation: at each grid point its
    y is 3 times the lag's y one step before (its input held over the step from there), and the lag's run is
    fmpy's."""
    address = str(inprocess_gateway.address)
    (tmp_path / "gain.toml").write_text('[inputs]\nu = "Lag.y"\n[outputs]\ny = "Gain.y"\n')
    fed = tmp_path / "chain.fed"
    fed.write_text(Mapping(outputs={"lag": Endpoint("Lag", "y"), "gain": Endpoint("Gain", "y")}).fed("Chain"))
    rti.RTIAmbassador(address).createFederationExecution("Chain", str(fed))
    lag = FmuFederate(lag_fmu, "Chain", step_size=H, address=address,
                      mapping=Mapping(outputs={"y": Endpoint("Lag", "y")}), start_values={"u": 1.0}, timeout=20.0)
    gain = FmuFederate(gain_fmu, "Chain", step_size=H, address=address, mapping=tmp_path / "gain.toml",
                       start_values={"k": 3.0}, timeout=20.0)
    try:
        lag.join()
        gain.join()
        with running(lag, gain) as failures:
            pass
        assert not failures, failures
    finally:
        lag.close()
        gain.close()
    rti.RTIAmbassador(address).destroyFederationExecution("Chain")
    expected = fmpy.simulate_fmu(str(lag_fmu), stop_time=STEPS * H, output_interval=H, start_values={"u": 1.0},
                                 output=["y"])
    lag_y = [v["y"] for _, v in lag.trajectory]
    assert lag_y == pytest.approx(list(expected["y"]), rel=1e-12)
    gain_y = [v["y"] for _, v in gain.trajectory]
    assert gain_y[1:] == pytest.approx([3.0 * y for y in lag_y[:-1]], rel=1e-12)
    assert gain_y[-1] > 1.5


def test_an_output_that_follows_its_input_directly_goes_out_at_the_inputs_time(gateway_address: str,
                                                                              tmp_path: pathlib.Path,
                                                                              tmp_path_factory: pytest.TempPathFactory
                                                                              ) -> None:
    """The C gain of tests/data/fmu/gain2 declares y = 2 u with direct feedthrough: the federate steps with
    lookahead 0 and sends y stamped at the time of the u it follows, so the feeder's grant of t brings
    y(t) = 2 u(t), without the step of delay of FMPy's loop (asked with feedthrough=False: y(t + h) = 2 u(t))."""
    gain_fmu = build_fmu("gain2", tmp_path_factory.getbasetemp() / "fmus")
    fed = tmp_path / "gain.fed"
    fed.write_text(Mapping.by_name(FmuModel(gain_fmu)).fed("GainFed"))
    runs = {}
    for feedthrough in (True, False):
        rti.RTIAmbassador(gateway_address).createFederationExecution("GainFed", str(fed))
        feeder = Federate(gateway_address, "feeder", federation="GainFed")
        try:
            feeder.enable_time(lookahead=H * (1 - LOOKAHEAD_MARGIN))
            gain = feeder.rtia.getObjectClassHandle("Gain")
            u, y = (feeder.rtia.getAttributeHandle(name, gain) for name in ("u", "y"))
            feeder.rtia.publishObjectClass(gain, [u])
            feeder.rtia.subscribeObjectClassAttributes(gain, [y])
            source = feeder.rtia.registerObjectInstance(gain, "source")
            with FmuFederate(gain_fmu, "GainFed", step_size=H, address=gateway_address, timeout=20.0,
                             start_values={"u": signal(0)}, feedthrough=None if feedthrough else False) as federate:
                assert federate.feedthrough is feedthrough
                federate.join()
                assert not run_beside(federate, feeder, lambda k: feeder.rtia.updateAttributeValues(
                    source, {u: F64.pack(signal(k))}, "feeder", k * H))
                assert federate.lookahead == (0.0 if feedthrough else H * (1 - LOOKAHEAD_MARGIN))
        finally:
            feeder.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
            rti.RTIAmbassador(gateway_address).destroyFederationExecution("GainFed")
        # each reflection of y, and the grant it came before
        seen, grant = [], 0.0
        for name, args in reversed(feeder.amb.calls):
            if name == "timeAdvanceGrant":
                grant = args[0]
            elif name == "reflectAttributeValues" and y in args[1]:
                seen.append((args[5], grant, F64.unpack(args[1][y])[0]))
        runs[feedthrough] = sorted(seen)
    assert [t for t, _, _ in runs[True]] == pytest.approx([k * H for k in range(1, STEPS + 1)])
    assert [g for _, g, _ in runs[True]] == [t for t, _, _ in runs[True]]  # y(t) came with the grant of t
    assert [v for _, _, v in runs[True]] == pytest.approx([2 * signal(min(k, STEPS - 1)) for k in range(1, STEPS + 1)],
                                                          rel=1e-15)
    assert [t for t, _, _ in runs[False]] == pytest.approx([k * H for k in range(1, STEPS + 1)])
    assert [v for _, _, v in runs[False]] == pytest.approx([2 * signal(k - 1) for k in range(1, STEPS + 1)], rel=1e-15)


def test_an_input_stamped_after_a_feedthrough_fmu_took_its_inputs_is_an_input_error(
        gateway_address: str, tmp_path: pathlib.Path, tmp_path_factory: pytest.TempPathFactory) -> None:
    """A feeder with lookahead 0 (as another FMU with direct feedthrough would be) is granted 0.2 "available",
    like the gain, and sends u stamped 0.2 once the gain has taken its inputs of 0.2: the gain cannot use it at
    0.2 any more, and says so with InputError at its next step, after resigning."""
    gain_fmu = build_fmu("gain2", tmp_path_factory.getbasetemp() / "fmus")
    fed = tmp_path / "gain.fed"
    fed.write_text(Mapping.by_name(FmuModel(gain_fmu)).fed("GainFed"))
    rti.RTIAmbassador(gateway_address).createFederationExecution("GainFed", str(fed))
    feeder = Federate(gateway_address, "feeder", federation="GainFed")
    try:
        feeder.enable_time(lookahead=0.0)
        gain = feeder.rtia.getObjectClassHandle("Gain")
        u = feeder.rtia.getAttributeHandle("u", gain)
        feeder.rtia.publishObjectClass(gain, [u])
        source = feeder.rtia.registerObjectInstance(gain, "source")
        with FmuFederate(gain_fmu, "GainFed", step_size=H, address=gateway_address, timeout=20.0) as federate:
            federate.join()
            with running(federate) as failures:
                for k in (1, 2):
                    feeder.rtia.timeAdvanceRequestAvailable(k * H)
                    feeder.rtia.await_grant(timeout=20.0)
                    tick_until(lambda: federate.pending == pytest.approx((k + 1) * H), feeder.rtia)  # took u(k h)
                feeder.rtia.updateAttributeValues(source, {u: F64.pack(1.0)}, "feeder", 2 * H)
                feeder.rtia.timeAdvanceRequestAvailable(3 * H)
                feeder.rtia.await_grant(timeout=20.0)
    finally:
        feeder.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        rti.RTIAmbassador(gateway_address).destroyFederationExecution("GainFed")  # the gain resigned
    assert [type(error) for error in failures] == [InputError]
    assert "u: instance 'source' sent a value stamped 0.2 after the inputs of 0.2 were taken" in str(failures[0])


def test_direct_feedthrough_and_state_saving_are_read_from_the_model_description(
        lag_fmu: pathlib.Path, gain_fmu: pathlib.Path, tmp_path_factory: pytest.TempPathFactory) -> None:
    """The lags declare y independent of u and their state saveable; the pythonfmu gain declares no dependencies
    (so y depends on u, by the standard) and no state saving."""
    lag3 = build_fmu("lag3", tmp_path_factory.getbasetemp() / "fmus")
    assert [(FmuModel(f).direct_feedthrough, FmuModel(f).can_save_state) for f in (lag_fmu, lag3, gain_fmu)] \
        == [(False, True), (False, True), (True, False)]
