"""Reading hlacore's recordings: what ``rtig --record FILE``, ``hlacore.Gateway(record=FILE)`` and the
recorder federate (``python -m hlacore.record``) write (docs/record-replay.md).

A recording is an MCAP file (https://mcap.dev) of JSON messages, one per event, in the order the gateway saw
them (their MCAP sequence number), stamped with the gateway's wall clock. For a federation ``F`` the topics
are:

``/F/federation``
    ``created`` (the FED file's name and text), ``joined``, ``dropped`` (with the reason);
``/F/objects/CLASS``
    ``register``, ``update`` and ``delete`` of the instances of object class ``CLASS`` (its qualified name),
    with the attribute values;
``/F/interactions/CLASS``
    the interactions of that class, with the parameter values;
``/F/hlacore/requests``, ``/F/hlacore/refusals``, ``/F/hlacore/callbacks``, ``/F/hlacore/grants``
    every other request of a federate, the requests refused with an exception, the callbacks the gateway
    sent (all but reflections and received interactions) and the grants.

Every event names its federate (``federate``, ``handle``) and that federate's logical time then
(``federate_time``). Values are the bytes the federates sent (base64 in the file; :meth:`Event.values` gives
bytes), to decode with :mod:`hlacore.omt` and the FOM's types. MCAP tools (Foxglove, the ``mcap`` CLI and
library) open a recording as it is; :func:`read` is the strict reader of hlacore's own tools, whose errors
name the byte offset of the damage.
"""

from __future__ import annotations

import base64
import json
import os
import struct
from dataclasses import dataclass
from io import BytesIO
from typing import Any, BinaryIO, Iterator, Optional

from mcap.data_stream import ReadDataStream
from mcap.opcode import Opcode
from mcap.records import Channel, Chunk, Message
from mcap.stream_reader import breakup_chunk

__all__ = ["RecordingError", "Event", "read", "MAGIC"]

#: The first and last eight bytes of an MCAP file.
MAGIC = b"\x89MCAP0\r\n"


class RecordingError(Exception):
    """A recording that is not one, damaged or cut short: names the file and the byte offset."""

    def __init__(self, path: str, offset: int, reason: str) -> None:
        super().__init__(f"{path}: {reason} (at byte offset {offset})")
        self.path = path
        self.offset = offset
        self.reason = reason


@dataclass(frozen=True)
class Event:
    """One recorded event."""

    sequence: int
    """Its place in the recording: the order the gateway saw the events in."""
    wall_ns: int
    """When the gateway recorded it: nanoseconds since the epoch (CLOCK_REALTIME)."""
    federation: str
    topic: str
    """The topic below the federation: ``federation``, ``objects/CLASS``, ``interactions/CLASS``,
    ``hlacore/requests``, ``hlacore/refusals``, ``hlacore/callbacks`` or ``hlacore/grants``."""
    data: dict[str, Any]
    """The message as recorded."""
    offset: int
    """The byte offset of the record (or chunk) holding it."""

    @property
    def kind(self) -> str:
        """``register``, ``update``, ``delete``, ``interaction``, ``grant``, ``request``, ``refusal``,
        ``callback``, ``created``, ``joined`` or ``dropped``."""
        if self.topic == "federation":
            return str(self.data["event"])
        if self.topic.startswith(("objects/", "interactions/")):
            return str(self.data["kind"])
        return {"hlacore/grants": "grant", "hlacore/requests": "request", "hlacore/refusals": "refusal",
                "hlacore/callbacks": "callback"}[self.topic]

    @property
    def federate(self) -> Optional[str]:
        """The federate it concerns (sender, or receiver of a callback); None for ``created``."""
        name = self.data.get("federate")
        return None if name is None else str(name)

    @property
    def class_name(self) -> Optional[str]:
        """The object or interaction class of an object event or an interaction."""
        for prefix in ("objects/", "interactions/"):
            if self.topic.startswith(prefix):
                return self.topic[len(prefix):]
        return None

    @property
    def message(self) -> Optional[str]:
        """The wire message of a request, callback or refusal (``TimeAdvance``, ``AnnounceSyncPoint``...)."""
        for key in ("request", "callback", "answer"):
            if key in self.data:
                return str(self.data[key])
        return None

    def values(self) -> dict[str, bytes]:
        """The attribute or parameter values of an update or interaction, by name."""
        raw = self.data.get("attributes", self.data.get("parameters", {}))
        return {name: base64.b64decode(value) for name, value in raw.items()}

    def tag(self) -> bytes:
        """The user-supplied tag of an update, interaction or deletion."""
        return decode_text(self.data.get("tag", ""))


def decode_text(value: Any) -> bytes:
    """A recorded byte string: a JSON string (its UTF-8) or ``{"base64": ...}``."""
    if isinstance(value, dict):
        return base64.b64decode(value["base64"])
    return str(value).encode()


_SUFFIXES = ("/objects/", "/interactions/", "/hlacore/")


def _split_topic(topic: str) -> tuple[str, str]:
    if topic.endswith("/federation"):
        return topic[1:-len("/federation")], "federation"
    for suffix in _SUFFIXES:
        at = topic.rfind(suffix)
        if at > 0:
            return topic[1:at], topic[at + 1:]
    raise ValueError(f"not a topic of an hlacore recording: {topic!r}")


def _record_name(opcode: int) -> str:
    try:
        return Opcode(opcode).name.lower()
    except ValueError:
        return f"unknown (opcode {opcode:#x})"


def read(path: str | os.PathLike[str]) -> Iterator[Event]:
    """The events of the recording at ``path``, in the order they were recorded. Channels that are not JSON
    (ROS topics merged in by ``hlacore.federates.ros_bridge.recorder.merge``) are skipped.

    Raises :class:`RecordingError` naming the byte offset when the file is not an MCAP file, a record is
    damaged (a chunk's CRC does not match, a message is not JSON) or the file was cut short (the gateway was
    killed before it closed the recording: the events before the damage have been yielded by then).
    """
    name = os.fspath(path)
    with open(name, "rb") as file:
        yield from _events(name, file, os.fstat(file.fileno()).st_size)


def _events(path: str, file: BinaryIO, size: int) -> Iterator[Event]:
    """Reads the file's records one by one (memory: the largest chunk), checking each against `size`."""
    if size == 0:
        raise RecordingError(path, 0, "empty file, not a recording")
    if file.read(8) != MAGIC:
        raise RecordingError(path, 0, "not an MCAP file (its first bytes are not MCAP's magic)")
    topics: dict[int, tuple[str, str]] = {}
    foreign: set[int] = set()  # channels that are not the gateway's (ROS topics merged in): skipped
    pos = 8
    while True:
        if pos + 9 > size:
            raise RecordingError(path, pos, "cut short: the file ends before the recording's end (the gateway or "
                                            "recorder stopped without closing it)")
        opcode, length = struct.unpack("<BQ", file.read(9))
        end = pos + 9 + length
        if end > size:
            raise RecordingError(path, pos, f"cut short: a record of {length} bytes ends {end - size} bytes beyond "
                                            f"the end of the file")
        content = file.read(length)
        if opcode in (Opcode.DATA_END, Opcode.FOOTER):
            break
        try:
            if opcode == Opcode.CHUNK:
                chunk = Chunk.read(ReadDataStream(BytesIO(content)))
                records: list[Any] = breakup_chunk(chunk, validate_crc=True)
            elif opcode == Opcode.CHANNEL:
                records = [Channel.read(ReadDataStream(BytesIO(content)))]
            elif opcode == Opcode.MESSAGE:
                records = [Message.read(ReadDataStream(BytesIO(content)), length)]
            else:
                records = []
        except Exception as e:  # the mcap library's errors: struct.error, ValueError, McapError
            raise RecordingError(path, pos, f"damaged {_record_name(opcode)} record: {e}") from None
        for record in records:
            if isinstance(record, Channel):
                if record.message_encoding != "json":
                    foreign.add(record.id)
                    continue
                try:
                    topics[record.id] = _split_topic(record.topic)
                except ValueError as e:
                    raise RecordingError(path, pos, str(e)) from None
            elif isinstance(record, Message):
                if record.channel_id in foreign:
                    continue
                if record.channel_id not in topics:
                    raise RecordingError(path, pos, f"message {record.sequence} on channel {record.channel_id}, "
                                                    f"which no channel record announced")
                try:
                    data = json.loads(record.data)
                except ValueError as e:
                    raise RecordingError(path, pos, f"message {record.sequence} is not JSON: {e}") from None
                if not isinstance(data, dict):
                    raise RecordingError(path, pos, f"message {record.sequence} is not a JSON object")
                federation, topic = topics[record.channel_id]
                yield Event(record.sequence, record.log_time, federation, topic, data, pos)
        pos = end
    file.seek(size - 8)
    if file.read(8) != MAGIC:
        raise RecordingError(path, pos, "cut short after its data: the summary and footer are incomplete")
