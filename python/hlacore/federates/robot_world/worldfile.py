"""A reader for the subset of Stage's ``.world`` format that the robot world understands.

Lexical rules are Stage's: ``#`` comments, ``include "file"``, ``define NEW PARENT ( props )``
prototypes, entities ``TYPE ( props and child entities )``, properties ``key value`` or
``key [ v1 v2 ... ]``. Lengths are metres (``unit_length`` "m", "cm" or "mm"); angles are degrees
unless ``unit_angle "radians"``.

Understood: top-level ``interval_sim`` (ms), ``resolution`` and ``speedup`` (kept, unused);
``window`` (ignored, GUI only); ``position`` with ``pose``, ``size``, ``origin``, ``drive``,
``velocity_bounds``, ``color``, ``name``, ``localization``, ``odom_error`` and ``ranger`` children;
``ranger`` with ``sensor( pose range fov samples noise )`` (or the older ``range_max`` /
``view [min max fov]``); plain ``model`` (and ``floorplan`` without bitmap) obstacles with ``pose``,
``size``, ``obstacle_return``, ``ranger_return`` / ``laser_return``, ``boundary``. Anything else is
read and ignored, so existing worlds load.
"""

from __future__ import annotations

import math
import pathlib
import re
from dataclasses import dataclass, field
from typing import Any, Optional, Union

Value = Union[str, float, list[Any]]

_TOKEN = re.compile(r'\s*(?:(#[^\n]*)|("(?:[^"\\]|\\.)*")|([()\[\]])|([^\s()\[\]"#]+))')


class WorldFileError(ValueError):
    """A .world file that cannot be read: the message names the file and line."""


@dataclass
class SensorSpec:
    """One ranger sensor: pose in the robot frame (x, y, heading in radians), beams and noise."""

    pose: tuple[float, float, float] = (0.0, 0.0, 0.0)
    range_min: float = 0.0
    range_max: float = 5.0
    fov: float = 0.1  # radians (Stage's default)
    samples: int = 1
    noise: float = 0.0  # standard deviation of the range noise, metres


@dataclass
class RobotSpec:
    """A Stage ``position`` model: a differential-drive robot."""

    name: str
    pose: tuple[float, float, float]  # x, y, heading (radians)
    size: tuple[float, float] = (0.1, 0.1)
    origin: tuple[float, float] = (0.0, 0.0)
    color: str = "red"
    drive: str = "diff"
    max_linear: float = 1.0
    max_angular: float = math.pi / 2
    odom_noise: tuple[float, float] = (0.0, 0.0)  # relative std dev on linear and angular speed
    sensors: list[SensorSpec] = field(default_factory=list)


@dataclass
class BlockSpec:
    """A static ``model``: a box that robots hit (``obstacle_return``) and rangers see (``ranger_return``)."""

    pose: tuple[float, float, float]
    size: tuple[float, float]
    color: str = "gray30"
    name: str = ""
    obstacle: bool = True
    visible: bool = True


@dataclass
class WorldSpec:
    """What a .world file describes, in SI units."""

    interval_sim: float = 0.1  # seconds per Stage update
    resolution: float = 0.02
    robots: list[RobotSpec] = field(default_factory=list)
    blocks: list[BlockSpec] = field(default_factory=list)


@dataclass
class _Entity:
    kind: str
    props: dict[str, Value] = field(default_factory=dict)
    children: list["_Entity"] = field(default_factory=list)
    line: int = 0


def _tokens(text: str, source: str) -> list[tuple[str, int]]:
    """Split into (token, line) pairs, comments dropped."""
    out: list[tuple[str, int]] = []
    pos, line, counted = 0, 1, 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            if text[pos:].strip() == "":
                break
            line += text.count("\n", counted, pos)
            raise WorldFileError(f"{source}:{line}: unexpected character {text[pos]!r}")
        token = m.group(2) or m.group(3) or m.group(4)
        if token is not None:
            start = m.end() - len(token)
            line += text.count("\n", counted, start)
            counted = start
            out.append((token, line))
        pos = m.end()
    return out


def _atom(token: str) -> Value:
    if token.startswith('"'):
        return token[1:-1]
    try:
        return float(token)
    except ValueError:
        return token


class _Parser:
    def __init__(self, path: Optional[pathlib.Path], text: str) -> None:
        self.base = path.parent if path else pathlib.Path(".")
        self.source = str(path) if path else "<string>"
        self.defines: dict[str, _Entity] = {}
        self.top: dict[str, Value] = {}
        self.entities: list[_Entity] = []
        self._run(text, self.source, self.entities, self.top, depth=0)

    def _run(self, text: str, source: str, entities: list[_Entity], props: dict[str, Value], depth: int) -> None:
        if depth > 16:
            raise WorldFileError(f"{source}: include nesting deeper than 16")
        toks = _tokens(text, source)
        i = 0
        while i < len(toks):
            tok, line = toks[i]
            if tok == "include":
                if i + 1 >= len(toks):
                    raise WorldFileError(f"{source}:{line}: include without a file")
                name = str(_atom(toks[i + 1][0]))
                inc = self.base / name
                try:
                    inc_text = inc.read_text()
                except OSError as exc:
                    raise WorldFileError(f"{source}:{line}: cannot include {name!r}: {exc}") from None
                self._run(inc_text, str(inc), entities, props, depth + 1)
                i += 2
            elif tok == "define":
                if i + 3 >= len(toks) or toks[i + 3][0] != "(":
                    raise WorldFileError(f"{source}:{line}: expected 'define NAME PARENT ( ... )'")
                name = toks[i + 1][0]
                entity, i = self._body(toks, i + 4, toks[i + 2][0], source, line)
                self.defines[name] = entity
            else:
                i = self._statement(toks, i, source, entities, props)

    def _statement(self, toks: list[tuple[str, int]], i: int, source: str,
                   entities: list[_Entity], props: dict[str, Value]) -> int:
        tok, line = toks[i]
        if tok in "()[]":
            raise WorldFileError(f"{source}:{line}: unexpected {tok!r}")
        if i + 1 < len(toks) and toks[i + 1][0] == "(":
            entity, j = self._body(toks, i + 2, tok, source, line)
            entities.append(entity)
            return j
        if i + 1 >= len(toks):
            raise WorldFileError(f"{source}:{line}: property {tok!r} without a value")
        value, j = self._value(toks, i + 1, source)
        props[tok] = value
        return j

    def _value(self, toks: list[tuple[str, int]], i: int, source: str) -> tuple[Value, int]:
        tok, line = toks[i]
        if tok == "[":
            items: list[Any] = []
            i += 1
            while i < len(toks) and toks[i][0] != "]":
                if toks[i][0] in "()[":
                    raise WorldFileError(f"{source}:{toks[i][1]}: unexpected {toks[i][0]!r} in a tuple")
                items.append(_atom(toks[i][0]))
                i += 1
            if i >= len(toks):
                raise WorldFileError(f"{source}:{line}: unclosed '['")
            return items, i + 1
        if tok in "()]":
            raise WorldFileError(f"{source}:{line}: unexpected {tok!r}")
        return _atom(tok), i + 1

    def _body(self, toks: list[tuple[str, int]], i: int, kind: str, source: str, line: int) -> tuple[_Entity, int]:
        entity = _Entity(kind, line=line)
        while True:
            if i >= len(toks):
                raise WorldFileError(f"{source}:{line}: unclosed '(' of {kind!r}")
            if toks[i][0] == ")":
                return entity, i + 1
            i = self._statement(toks, i, source, entity.children, entity.props)


_BUILTIN = {"position", "ranger", "model", "floorplan", "window", "sensor", "block"}


def _resolve(entity: _Entity, defines: dict[str, _Entity], depth: int = 0) -> _Entity:
    """Expand prototypes: a defined type's properties and children, overridden by the entity's own."""
    if entity.kind not in defines or depth > 32:
        return entity
    base = _resolve(defines[entity.kind], defines, depth + 1)
    return _Entity(base.kind, {**base.props, **entity.props}, base.children + entity.children, entity.line)


class _Units:
    def __init__(self, props: dict[str, Value]) -> None:
        self.length = {"m": 1.0, "cm": 0.01, "mm": 0.001}.get(str(props.get("unit_length", "m")), 1.0)
        self.angle = 1.0 if str(props.get("unit_angle", "degrees")) == "radians" else math.pi / 180.0

    def nums(self, value: Value, n: int, default: list[float]) -> list[float]:
        """The first ``n`` numbers of ``value`` (one number or a list), completed from ``default``."""
        items = value if isinstance(value, list) else [value]
        out = [float(v) for v in items] + default[len(items):]
        return out[:n]

    def pose(self, props: dict[str, Value]) -> tuple[float, float, float]:
        """The ``pose`` property as ``(x, y, a)`` in metres and radians (z dropped)."""
        x, y, _z, a = self.nums(props.get("pose", [0, 0, 0, 0]), 4, [0.0, 0.0, 0.0, 0.0])
        return (x * self.length, y * self.length, a * self.angle)

    def size(self, props: dict[str, Value], default: list[float]) -> tuple[float, float]:
        """The ``size`` property (else ``default``) as ``(sx, sy)`` in metres."""
        sx, sy = self.nums(props.get("size", default), 2, default)
        return (sx * self.length, sy * self.length)


def _compose(parent: tuple[float, float, float], child: tuple[float, float, float]) -> tuple[float, float, float]:
    px, py, pa = parent
    cx, cy, ca = child
    c, s = math.cos(pa), math.sin(pa)
    return (px + c * cx - s * cy, py + s * cx + c * cy, pa + ca)


def _sensors(ranger: _Entity, units: _Units, defines: dict[str, _Entity]) -> list[SensorSpec]:
    ranger_pose = units.pose(ranger.props)
    out = []
    children = [_resolve(c, defines) for c in ranger.children]
    sensors = [c for c in children if c.kind == "sensor"] or [_Entity("sensor", ranger.props)]
    for sensor in sensors:
        props = sensor.props
        spec = SensorSpec(pose=_compose(ranger_pose, units.pose(props)))
        if "range" in props:
            lo, hi = units.nums(props["range"], 2, [0.0, 5.0])
            spec.range_min, spec.range_max = lo * units.length, hi * units.length
        if "range_max" in props:
            spec.range_max = float(units.nums(props["range_max"], 1, [5.0])[0]) * units.length
        if "view" in props:
            lo, hi, fov = units.nums(props["view"], 3, [0.0, 5.0, 0.0])
            spec.range_min, spec.range_max, spec.fov = lo * units.length, hi * units.length, fov * units.angle
        if "fov" in props:
            spec.fov = units.nums(props["fov"], 1, [0.0])[0] * units.angle
        if "samples" in props:
            spec.samples = max(1, int(units.nums(props["samples"], 1, [1.0])[0]))
        if "noise" in props:
            spec.noise = units.nums(props["noise"], 1, [0.0])[0] * units.length
        out.append(spec)
    return out


def _robot(entity: _Entity, index: int, units: _Units, defines: dict[str, _Entity]) -> RobotSpec:
    props = entity.props
    name = str(props.get("name") or f"robot_{index}")
    vb = units.nums(props.get("velocity_bounds", [-1, 1, -1, 1, -1, 1, -90, 90]), 8,
                    [-1.0, 1.0, -1.0, 1.0, -1.0, 1.0, -90.0, 90.0])
    ox, oy = units.nums(props.get("origin", [0, 0, 0, 0]), 2, [0.0, 0.0])
    robot = RobotSpec(
        name=name,
        pose=units.pose(props),
        size=units.size(props, [0.1, 0.1]),  # Stage's model default
        origin=(ox * units.length, oy * units.length),
        color=str(props.get("color", "red")),
        drive=str(props.get("drive", "diff")),
        max_linear=max(abs(vb[0]), abs(vb[1])) * units.length,
        max_angular=max(abs(vb[6]), abs(vb[7])) * units.angle,
    )
    if str(props.get("localization", "gps")) == "odom" and "odom_error" in props:
        err = units.nums(props["odom_error"], 4, [0.03, 0.03, 0.0, 0.05])
        robot.odom_noise = (err[0], err[3])
    for child in entity.children:
        child = _resolve(child, defines)
        if child.kind == "ranger":
            robot.sensors.extend(_sensors(child, units, defines))
    return robot


def _number(props: dict[str, Value], key: str, default: float) -> float:
    """A scalar property (the first element of a tuple)."""
    value = props.get(key, default)
    if isinstance(value, list):
        value = value[0] if value else default
    try:
        return float(value)
    except (TypeError, ValueError):
        return default


def _blocks(entity: _Entity, units: _Units) -> list[BlockSpec]:
    props = entity.props
    visible = _number(props, "ranger_return", _number(props, "laser_return", 1.0)) >= 0.0
    obstacle = _number(props, "obstacle_return", 1.0) != 0.0
    pose = units.pose(props)
    size = units.size(props, [0.1, 0.1])
    color = str(props.get("color", "gray30" if entity.kind == "floorplan" else "red"))
    name = str(props.get("name", ""))
    if _number(props, "boundary", 0.0):
        # Stage's bounding box: four thin walls on the model's outline.
        sx, sy = size
        t = 0.02
        edges = [((0.0, (sy - t) / 2), (sx, t)), ((0.0, -(sy - t) / 2), (sx, t)),
                 (((sx - t) / 2, 0.0), (t, sy)), ((-(sx - t) / 2, 0.0), (t, sy))]
        return [BlockSpec(_compose(pose, (ex, ey, 0.0)), esize, color, name, obstacle, visible)
                for (ex, ey), esize in edges]
    if entity.kind == "floorplan" and props.get("bitmap"):
        return []  # bitmaps are not supported: the floorplan is left out (documented)
    return [BlockSpec(pose, size, color, name, obstacle, visible)]


def load_world(text: str, path: Optional[pathlib.Path] = None) -> WorldSpec:
    """Read .world text (``path`` resolves includes and names the file in errors)."""
    parser = _Parser(path, text)
    units = _Units(parser.top)
    spec = WorldSpec()
    if "interval_sim" in parser.top:
        spec.interval_sim = float(units.nums(parser.top["interval_sim"], 1, [100.0])[0]) / 1000.0
    if "resolution" in parser.top:
        spec.resolution = float(units.nums(parser.top["resolution"], 1, [0.02])[0])
    for raw in parser.entities:
        entity = _resolve(raw, parser.defines)
        if entity.kind == "position":
            spec.robots.append(_robot(entity, len(spec.robots), units, parser.defines))
        elif entity.kind in ("model", "floorplan", "block"):
            spec.blocks.extend(_blocks(entity, units))
    names = [r.name for r in spec.robots]
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise WorldFileError(f"{parser.source}: robot names are not unique: {duplicates}")
    return spec


def read_world(path: Union[str, pathlib.Path]) -> WorldSpec:
    """Read a .world file."""
    p = pathlib.Path(path)
    return load_world(p.read_text(), p)
