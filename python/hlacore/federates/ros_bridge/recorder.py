"""The bridged ROS topics in MCAP, beside the federation's events (docs/ros-bridge.md, "Recording").

:class:`TopicRecorder` writes what a bridge publishes and receives on ROS, one channel per topic, each message
as it travels on the wire (ROS 2: CDR, schema ``ros2msg``; ROS 1: ``ros1``, ``ros1msg``) with the message's
definition as its schema, so Foxglove and the mcap tools decode it. The log time is the wall clock
(``CLOCK_REALTIME``, nanoseconds), as in the gateway's recordings; the publish time is the message's
``header.stamp`` (``/clock``'s clock), federation time when the bridge is timed, else the log time.

:func:`merge` then puts such a file into the gateway's recording of the same run (``rtig --record``,
``hlacore.Gateway(record=...)``): one MCAP file, messages in log-time order, the federation's topics and
schemas untouched. :func:`hlacore.recording.read` skips the ROS channels (they are not JSON).
"""

from __future__ import annotations

import heapq
import os
import threading
import time
from typing import Any, BinaryIO, Iterator, Optional

from mcap.reader import make_reader
from mcap.writer import CompressionType, Writer

from .ros_api import RosApi


class TopicRecorder:
    """An MCAP file of ROS messages, written from any thread (:meth:`record`), closed by :meth:`close`."""

    def __init__(self, path: str | os.PathLike[str], ros: RosApi) -> None:
        self.path = os.fspath(path)
        self.ros = ros
        self.count = 0  #: messages recorded
        self._file: BinaryIO = open(self.path, "wb")
        self._writer = Writer(self._file, compression=CompressionType.NONE)
        self._writer.start(profile="ros2" if ros.version == 2 else "ros1", library="hlacore ros_bridge")
        self._schemas: dict[Any, int] = {}  # message class -> schema id
        self._channels: dict[str, int] = {}  # topic -> channel id
        self._lock = threading.Lock()

    def record(self, topic: str, msg: Any) -> None:
        """Write ``msg`` as published or received on ``topic`` now."""
        data = self.ros.serialize(msg)
        now = time.time_ns()
        header = getattr(msg, "header", None)
        stamp = getattr(msg, "clock", None) if header is None else header.stamp
        publish = now if stamp is None else round(self.ros.seconds(stamp) * 1e9)
        with self._lock:
            if self._writer is None:
                return
            channel = self._channels.get(topic)
            if channel is None:
                kind = type(msg)
                schema = self._schemas.get(kind)
                if schema is None:
                    name, encoding, text = self.ros.schema(kind)
                    schema = self._schemas[kind] = self._writer.register_schema(name, encoding, text)
                channel = self._channels[topic] = self._writer.register_channel(topic, self.ros.message_encoding,
                                                                               schema)
            self._writer.add_message(channel, log_time=now, data=data, publish_time=publish,
                                     sequence=self.count)
            self.count += 1

    def close(self) -> None:
        """Finish the file (summary and index written); later :meth:`record` calls do nothing."""
        with self._lock:
            if self._writer is not None:
                self._writer.finish()
                self._file.close()
                self._writer = None  # type: ignore[assignment]


def merge(recording: str | os.PathLike[str], topics: str | os.PathLike[str],
          output: Optional[str | os.PathLike[str]] = None) -> int:
    """Write into ``output`` (default: ``recording``, replaced when done) the messages of the gateway's
    ``recording`` and of a :class:`TopicRecorder` file ``topics``, in log-time order (the recording's first
    at equal times), each with its own channel and schema; the header is the recording's. Returns the number
    of messages written."""
    target = os.fspath(output if output is not None else recording)
    partial = f"{target}.merging"
    with open(recording, "rb") as a, open(topics, "rb") as b, open(partial, "wb") as out:
        first = make_reader(a)
        header = first.get_header()
        writer = Writer(out, compression=CompressionType.NONE)
        writer.start(profile=header.profile, library=header.library)
        schemas: dict[tuple[int, int], int] = {}
        channels: dict[tuple[int, int], int] = {}
        written = 0
        for _time, _source, _n, (source, schema, channel, message) in heapq.merge(
                _keyed(0, first), _keyed(1, make_reader(b))):
            key = (source, channel.id)
            if key not in channels:
                schema_id = 0
                if schema is not None:
                    if (source, schema.id) not in schemas:
                        schemas[(source, schema.id)] = writer.register_schema(schema.name, schema.encoding,
                                                                              schema.data)
                    schema_id = schemas[(source, schema.id)]
                channels[key] = writer.register_channel(channel.topic, channel.message_encoding, schema_id,
                                                        dict(channel.metadata))
            writer.add_message(channels[key], log_time=message.log_time, data=message.data,
                               publish_time=message.publish_time, sequence=message.sequence)
            written += 1
        writer.finish()
    os.replace(partial, target)
    return written


def _keyed(source: int, reader: Any) -> Iterator[tuple[int, int, int, tuple[int, Any, Any, Any]]]:
    for n, (schema, channel, message) in enumerate(reader.iter_messages(log_time_order=True)):
        yield message.log_time, source, n, (source, schema, channel, message)
