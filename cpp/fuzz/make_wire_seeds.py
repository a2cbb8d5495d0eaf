"""Writes the wire fuzzer's seed corpus (cpp/fuzz/corpus/wire/): valid frames of most message types, one file
each, plus a few multi-frame streams as a federate would send them (every message also gets a generated
sample frame from wire_seeds.cpp, so this list may lag the message list). Field layouts follow
cpp/rti/wire/messages.hpp (little-endian; string = u32 length + bytes; vector = u32 count + elements;
optional time = u8 flag [+ f64]). Run it again after changing the message list: python3 make_wire_seeds.py"""

import pathlib
import re
import struct

ROOT = pathlib.Path(__file__).resolve().parents[2]
# The message list, read from its one declaration (X(Name) entries of HLACORE_MESSAGES, in code order).
_HEADER = (ROOT / "cpp" / "rti" / "wire" / "message_list.hpp").read_text()
_LIST = _HEADER.split("#define HLACORE_MESSAGES(X)")[1]
NAMES = re.findall(r"X\((\w+)\)", _LIST.split("\n\n")[0])  # up to the blank line ending the macro
CODE = {name: i for i, name in enumerate(NAMES, start=1)}
VERSION = int(re.search(r"kProtocolVersion = (\d+);", _HEADER).group(1))


def u8(v): return struct.pack("<B", v)
def u16(v): return struct.pack("<H", v)
def u32(v): return struct.pack("<I", v)
def u64(v): return struct.pack("<Q", v)
def f64(v): return struct.pack("<d", v)
def b(v): return u8(1 if v else 0)
def s(v): data = v.encode() if isinstance(v, str) else v; return u32(len(data)) + data
def hs(v): return u32(len(v)) + b"".join(u32(h) for h in v)
def hv(v): return u32(len(v)) + b"".join(u32(h) + s(x) for h, x in v)
def t(v): return b(False) if v is None else b(True) + f64(v)


def frame(name, payload=b""):
    return u32(2 + len(payload)) + u16(CODE[name]) + payload


FED = (ROOT / "tests" / "data" / "robot.fed").read_text()
# FOM modules added at join: a bundle (cpp/fed_parser/omt.hpp) of one module.
_CARS = (ROOT / "tests" / "data" / "rti1516e" / "cars.xml").read_text()
MODULES = f"hlacore FOM modules\n8 {len(_CARS.encode())}\ncars.xml{_CARS}"
MESSAGES = {
    "Hello": u32(0x484C4143) + u16(VERSION),
    "Welcome": u16(VERSION) + s("hlacore rtig") + u32(64 << 20) + s("") + u64(0x1234_5678_9ABC_DEF0) + u32(1400) + s(""),
    "Welcome-challenge": u16(VERSION) + s("hlacore rtig") + u32(64 << 20) + s(bytes(range(32))) + u64(0) + u32(0)
    + s(""),
    "Welcome-nonce": u16(VERSION) + s("hlacore rtig") + u32(64 << 20) + s("") + u64(0) + u32(0) + s(bytes(range(32))),
    "Ping": u32(1),
    "Pong": u32(1),
    "Authenticate": s(bytes(32)),
    "Authenticated": b(True) + s(""),
    "Authenticated-refused": b(False) + s("the gateway refused the secret"),
    "ClockProbe": u32(1) + u64(123_456_789),
    "ClockEcho": u32(1) + u64(123_456_789) + u64(987_654_321),
    "DatagramHello": u32(1),
    "DatagramPath": b"",
    "CreateFederation": u32(1) + s("TestFed") + s("robot.fed") + s(FED) + s("") + u8(0) + u8(0),
    "CreateFederation-by-name": u32(1) + s("TestFed") + s("robot.fed") + s("") + s("") + u8(2) + u8(1),
    "DestroyFederation": u32(2) + s("TestFed") + s(""),
    "JoinFederation": u32(3) + s("alice") + s("TestFed") + s("") + s("") + s(""),
    "JoinFederation-proof": u32(3) + s("alice") + s("TestFed") + s(bytes(32)) + s("") + s(""),
    "JoinFederation-modules": u32(3) + s("alice") + s("TestFed") + s("") + s(MODULES) + s("robot"),
    "ResignFederation": u32(4) + u8(3),
    "RegisterSyncPoint": s("start") + s("tag") + b(False) + hs([1, 2]),
    "SyncPointAchieved": s("start"),
    "PublishObjectClass": u32(1) + hs([1, 2]),
    "UnpublishObjectClass": u32(1),
    "SubscribeObjectClass": u32(1) + hs([2]) + b(True),
    "UnsubscribeObjectClass": u32(1),
    "PublishInteractionClass": u32(1),
    "UnpublishInteractionClass": u32(1),
    "SubscribeInteractionClass": u32(1) + b(False),
    "UnsubscribeInteractionClass": u32(1),
    "RegisterObject": u32(5) + u32(1) + s("robot-1"),
    "UpdateAttributes": u32(7) + hv([(1, b"\x00\x01"), (2, b"on")]) + s("tag") + t(3.5) + u64(9),
    "UpdateAttributes-receive-order": u32(7) + hv([(2, b"x" * 40)]) + s("") + t(None) + u64(0),
    "SendInteraction": u32(1) + hv([(1, b"go")]) + s("cmd") + t(2.0) + u64(1),
    "DeleteObject": u32(7) + s("bye") + t(None) + u64(2),
    "LocalDeleteObject": u32(7),
    "RequestObjectUpdate": u32(7) + hs([1]),
    "RequestClassUpdate": u32(1) + hs([1, 2]),
    "SetAdvisorySwitch": u8(1) + b(True),
    "Reply": u32(4) + u16(0) + s(""),
    "Reply-error": u32(3) + u16(34) + s("FederationExecutionDoesNotExist"),
    "SyncPointRegistrationSucceeded": s("start"),
    "SyncPointRegistrationFailed": s("start"),
    "AnnounceSyncPoint": s("start") + s("tag"),
    "FederationSynchronized": s("start"),
    "StartRegistration": u32(1),
    "StopRegistration": u32(1),
    "TurnInteractionsOn": u32(1),
    "TurnInteractionsOff": u32(1),
    "DiscoverObject": u32(7) + u32(1) + s("robot-1"),
    "ReflectAttributes": u32(7) + hv([(1, b"\x00\x01")]) + s("tag") + u8(2) + u8(1) + t(3.5) + u32(1) + u64(9),
    "ReceiveInteraction": u32(1) + hv([(1, b"go")]) + s("cmd") + u8(1) + u8(2) + t(None) + u32(2) + u64(1),
    "RemoveObject": u32(7) + s("bye") + t(4.0) + u32(1) + u64(2),
    "ProvideAttributeValueUpdate": u32(7) + hs([1, 2]),
    "EnableTimeRegulation": f64(0.0) + f64(1.0),
    "DisableTimeRegulation": b"",
    "EnableTimeConstrained": b"",
    "DisableTimeConstrained": b"",
    "TimeAdvance": u8(1) + f64(10.0),
    "TimeAdvance-NER": u8(3) + f64(float("inf")),
    "ModifyLookahead": f64(0.5),
    "SetAsynchronousDelivery": b(True),
    "Retract": u64(9),
    "QueryTime": u32(8) + u8(1),
    "TimeRegulationEnabled": f64(0.0),
    "TimeConstrainedEnabled": f64(0.0),
    "TimeAdvanceGrant": f64(10.0),
    "RequestRetraction": u32(1) + u64(9),
    "QueryStatus": u32(1) + u64(0) + u8(1),
    "RequestFederationSave": u32(9) + s("snap") + t(5.0),
    "FederateSaveComplete": b(True),
    "RequestFederationRestore": u32(10) + s("snap"),
    "FederateRestoreComplete": b(False),
    "InitiateFederateSave": s("snap"),
    "FederationSaved": b(False) + u8(5),
    "RestoreRequestAnswer": s("snap") + b(False) + s("no save labelled 'snap'"),
    "FederationRestoreBegun": b"",
    # SavedTime: time, lookahead, regulating, constrained, asynchronous, strict, receives above time, promise.
    "InitiateFederateRestore": s("snap") + u32(2) + f64(5.0) + f64(1.0) + b(True) + b(True) + b(False) + b(True)
    + b(False) + f64(6.0) + u64(3) + u32(1) + u32(1) + hs([1, 2]) + u32(1) + u32(1) + hs([2]) + hs([1]) + hs([])
    + u32(1) + u32(7) + u32(1) + s("robot-1") + hs([1, 2]) + b(True)
    # DDM: region 3 in space 1, subscribed for class 2 and interaction 4, associated with object 7's attribute 1.
    + u32(1) + u32(3) + u32(1) + hs([10, 20, 0, 100]) + u32(1) + u32(2) + u32(3) + hs([1])
    + u32(1) + u32(4) + u32(3) + u32(1) + u32(7) + u32(1) + u32(3) + u32(3)
    # HLA 4's directed interactions: interaction 4 published at class 2, subscribed universally.
    + u32(1) + u32(2) + hs([4]) + u32(0) + u32(1) + u32(2) + hs([4]),
    "FederationRestored": b(False) + u8(1),
    "FederationJoined": u32(3) + u32(2) + s(FED) + s("robot.fed") + u8(0),
    "ObjectRegistered": u32(5) + u32(7) + s("robot-1"),
    "AttributesReleased": u32(6) + hs([1, 2]),
    "StatusReport": u32(1) + s('{"server":"hlacore rtig","federations":[]}'),
    "TimeQueried": u32(8) + f64(4.5),
    "StartRecording": u32(9),
    "RecordedTopic": s("/TestFed/hlacore/grants") + s("hlacore.Grant") + s('{"type":"object"}'),
    "Recorded": s("/TestFed/hlacore/grants") + u32(3) + u64(1_700_000_000_000_000_000)
                + s('{"federate":"robot","handle":1,"federate_time":0,"time":1}'),
    "ReserveObjectNames": b(True) + u32(2) + s("r1") + s("r2"),
    "ReleaseObjectNames": u32(1) + s("r1"),
    "ObjectNamesReserved": b(False) + b(True) + u32(1) + s("r1"),
    "AbortFederationSave": u32(11),
    "AbortFederationRestore": u32(12),
    "QueryAttributeTransportation": u32(7) + u32(1),
    "QueryInteractionTransportation": u32(2) + u32(4),
    "AttributeTransportationReported": u32(7) + u32(1) + u8(2),
    "InteractionTransportationReported": u32(2) + u32(4) + u8(1),
    "SubscriptionRate": u32(2) + s("HLAslow"),
    "PublishDirectedInteractions": u32(2) + hs([4, 5]),
    "SubscribeDirectedInteractions": u32(2) + hs([4]) + hs([5]),
    "SendDirectedInteraction": u32(4) + u32(7) + hv([(1, b"stop")]) + s("tag") + t(2.5) + u64(9),
    "ReceiveDirectedInteraction": u32(4) + u32(7) + hv([(1, b"stop")]) + s("tag") + u8(2) + u8(1) + t(2.5) + u32(3) + u64(9),
}
STREAMS = {
    "stream-join-publish-update": ["Hello", "JoinFederation", "PublishObjectClass", "RegisterObject", "UpdateAttributes"],
    "stream-time": ["EnableTimeRegulation", "EnableTimeConstrained", "SendInteraction", "TimeAdvance", "Retract"],
    "stream-gateway": ["Welcome", "FederationJoined", "DiscoverObject", "ReflectAttributes", "TimeAdvanceGrant"],
    "stream-save": ["RequestFederationSave", "FederateSaveComplete", "RequestFederationRestore", "FederateRestoreComplete"],
}


def main():
    out = pathlib.Path(__file__).resolve().parent / "corpus" / "wire"
    out.mkdir(parents=True, exist_ok=True)
    for old in out.glob("*.bin"):
        old.unlink()
    for key, payload in MESSAGES.items():
        (out / f"{key}.bin").write_bytes(frame(key.split("-")[0], payload))
    for key, names in STREAMS.items():
        (out / f"{key}.bin").write_bytes(b"".join(frame(n, MESSAGES[n]) for n in names))
    # a frame cut short, as a read would leave it
    (out / "partial-frame.bin").write_bytes(frame("Hello", MESSAGES["Hello"]) + frame("JoinFederation", MESSAGES["JoinFederation"])[:9])


if __name__ == "__main__":
    main()
