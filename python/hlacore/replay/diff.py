"""The first divergence between two recordings (``python -m hlacore.replay diff A B``).

Each recording is cut into streams: per federate, the registrations, updates and deletions of each object
(by class and name), the interactions of each class, and the grants. Two recordings agree when every
stream holds the same events in the same order with the same timestamps, tags and values; handles, serial
numbers and wall-clock marks are not compared. The first divergence is the earliest, in federation time, of
the streams' first differences. Values that are JSON in both recordings (UTF-8 JSON objects, such as the
robot's reports) are compared as JSON, without the members named in ``ignore`` (wall-clock marks, say).
"""

from __future__ import annotations

import collections
import json
import math
import os
from dataclasses import dataclass
from typing import Any, Iterable, Optional

from hlacore.recording import Event, read

__all__ = ["Divergence", "Comparison", "compare", "streams"]

StreamKey = tuple[str, ...]


def _key(event: Event) -> Optional[StreamKey]:
    kind = event.kind
    if kind in ("register", "update", "delete"):
        return (event.federation, str(event.federate), "object", str(event.class_name), str(event.data["object"]))
    if kind == "interaction":
        return (event.federation, str(event.federate), "interaction", str(event.class_name))
    if kind == "grant":
        return (event.federation, str(event.federate), "grants")
    return None


def streams(events: Iterable[Event]) -> dict[StreamKey, list[Event]]:
    """The compared streams of a recording, each in recording order."""
    result: dict[StreamKey, list[Event]] = collections.defaultdict(list)
    for event in events:
        key = _key(event)
        if key is not None:
            result[key].append(event)
    return dict(result)


def _federation_time(event: Event) -> float:
    stamp = event.data.get("time")
    if stamp is None:
        stamp = event.data.get("federate_time")
    return math.inf if stamp is None else float(stamp)


def _strip(value: Any, ignore: frozenset[str]) -> Any:
    if isinstance(value, dict):
        return {k: _strip(v, ignore) for k, v in value.items() if k not in ignore}
    if isinstance(value, list):
        return [_strip(v, ignore) for v in value]
    return value


def _as_json(data: bytes) -> Any:
    try:
        return json.loads(data.decode("utf-8"))
    except ValueError:  # UnicodeDecodeError is one
        return None


def _same_value(a: bytes, b: bytes, ignore: frozenset[str]) -> bool:
    if a == b:
        return True
    if not ignore:
        return False
    ja, jb = _as_json(a), _as_json(b)
    return ja is not None and jb is not None and _strip(ja, ignore) == _strip(jb, ignore)


def _show(data: Optional[bytes], limit: int = 300) -> str:
    if data is None:
        return "(none)"
    try:
        text = data.decode("utf-8")
        shown = repr(text) if not text.isprintable() else text
    except UnicodeDecodeError:
        shown = "0x" + data.hex()
    return shown if len(shown) <= limit else shown[:limit] + f"... ({len(data)} bytes)"


@dataclass(frozen=True)
class Divergence:
    """Where two recordings first differ."""

    time: float
    """The federation time of the differing event (its timestamp, else its federate's time)."""
    stream: StreamKey
    what: str
    """What differs: ``attribute 'location'``, ``timestamp``, ``kind``, ``tag``, ``missing in B``..."""
    a: Optional[Event]
    b: Optional[Event]
    a_value: str
    b_value: str

    def describe(self, a_name: str = "A", b_name: str = "B") -> str:
        """A few lines for people."""
        federation, federate, *rest = self.stream
        event = self.a or self.b
        assert event is not None
        if rest[0] == "object":
            subject = f"{event.kind} of object {rest[2]!r} (class {rest[1]})"
        elif rest[0] == "interaction":
            subject = f"interaction {rest[1]}"
        else:
            subject = "grant"
        time = "end of the recording" if math.isinf(self.time) else f"federation time {self.time:g}"
        lines = [f"first divergence at {time}: {subject} by federate {federate!r} of {federation!r}, {self.what}"]
        for name, side, value in ((a_name, self.a, self.a_value), (b_name, self.b, self.b_value)):
            where = f"sequence {side.sequence}" if side is not None else "absent"
            lines.append(f"  {name} ({where}): {value}")
        return "\n".join(lines)


@dataclass(frozen=True)
class Comparison:
    """The outcome of :func:`compare`."""

    first: Optional[Divergence]
    counts_a: dict[str, int]
    counts_b: dict[str, int]
    differing: int
    """How many compared events differ (or are missing on one side)."""
    compared: int

    @property
    def same(self) -> bool:
        """Whether the recordings agree."""
        return self.first is None

    def summary(self) -> str:
        """One line per recording and one for the differences."""
        def counts(c: dict[str, int]) -> str:
            return ", ".join(f"{n} {k}" for k, n in sorted(c.items())) or "nothing"
        return (f"A: {counts(self.counts_a)}\nB: {counts(self.counts_b)}\n"
                f"{self.differing} of {self.compared} compared events differ")


def _difference(a: Event, b: Event, ignore: frozenset[str]) -> Optional[tuple[str, str, str]]:
    if a.kind != b.kind:
        return "kind", a.kind, b.kind
    if a.data.get("time") != b.data.get("time"):
        return "timestamp", str(a.data.get("time")), str(b.data.get("time"))
    if a.kind == "grant":
        return None
    if a.tag() != b.tag():
        return "tag", _show(a.tag()), _show(b.tag())
    va, vb = a.values(), b.values()
    for name in sorted(set(va) | set(vb)):
        x, y = va.get(name), vb.get(name)
        if x is None or y is None or not _same_value(x, y, ignore):
            noun = "attribute" if a.kind in ("register", "update", "delete") else "parameter"
            return f"{noun} {name!r}", _show(x), _show(y)
    return None


def compare(a: str | os.PathLike[str], b: str | os.PathLike[str], ignore: Iterable[str] = ()) -> Comparison:
    """Compare the recordings ``a`` and ``b`` (see the module docstring); raises
    :class:`~hlacore.recording.RecordingError` for a damaged file."""
    skip = frozenset(ignore)
    events_a, events_b = list(read(a)), list(read(b))
    sa, sb = streams(events_a), streams(events_b)
    first: Optional[Divergence] = None
    differing = compared = 0
    for key in sorted(set(sa) | set(sb)):
        xs, ys = sa.get(key, []), sb.get(key, [])
        stream_first: Optional[Divergence] = None
        for i in range(max(len(xs), len(ys))):
            x = xs[i] if i < len(xs) else None
            y = ys[i] if i < len(ys) else None
            compared += 1
            if x is None or y is None:
                found: Optional[tuple[str, str, str]] = (
                    "missing in A" if x is None else "missing in B", "(none)" if x is None else "present",
                    "(none)" if y is None else "present")
            else:
                found = _difference(x, y, skip)
            if found is None:
                continue
            differing += 1
            if stream_first is None:
                present = x if x is not None else y
                assert present is not None
                stream_first = Divergence(_federation_time(present), key, found[0], x, y, found[1], found[2])
        if stream_first is not None and (first is None or _order(stream_first) < _order(first)):
            first = stream_first
    counts_a = collections.Counter(e.kind for e in events_a if _key(e) is not None)
    counts_b = collections.Counter(e.kind for e in events_b if _key(e) is not None)
    return Comparison(first, dict(counts_a), dict(counts_b), differing, compared)


def _order(d: Divergence) -> tuple[float, int]:
    event = d.a or d.b
    assert event is not None
    return d.time, event.sequence
