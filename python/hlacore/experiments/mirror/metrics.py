"""Comparing trajectories: the symmetric Hausdorff distance between two paths (each a polyline of points),
and whether a path keeps a robot clear of a box."""

from __future__ import annotations

import math
from typing import Sequence

Point = tuple[float, float]


def _to_segment(p: Point, a: Point, b: Point) -> float:
    ax, ay = b[0] - a[0], b[1] - a[1]
    length2 = ax * ax + ay * ay
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * ax + (p[1] - a[1]) * ay) / length2))
    return math.hypot(p[0] - a[0] - t * ax, p[1] - a[1] - t * ay)


def to_path(p: Point, path: Sequence[Point]) -> float:
    """Distance from ``p`` to the polyline ``path``."""
    if len(path) == 1:
        return math.hypot(p[0] - path[0][0], p[1] - path[0][1])
    return min(_to_segment(p, a, b) for a, b in zip(path, path[1:]))


def deviation(path: Sequence[Point], reference: Sequence[Point]) -> float:
    """How far ``path`` strays from the polyline ``reference`` at worst (one-sided: a path that stops short
    of the reference's end still follows it)."""
    if not path or not reference:
        raise ValueError("both paths need at least one point")
    return max(to_path(p, reference) for p in path)


def hausdorff(a: Sequence[Point], b: Sequence[Point]) -> float:
    """The symmetric Hausdorff distance between polylines ``a`` and ``b``: how far one path strays from the
    other at worst (blind to timing, unlike a point-by-point comparison)."""
    return max(deviation(a, b), deviation(b, a))


def box_clearance(path: Sequence[Point], centre: Point, side: float) -> float:
    """The smallest distance from a point of ``path`` to the axis-aligned square box (negative inside)."""
    half = side / 2
    out = math.inf
    for x, y in path:
        dx, dy = abs(x - centre[0]) - half, abs(y - centre[1]) - half
        outside = math.hypot(max(dx, 0.0), max(dy, 0.0))
        out = min(out, outside if outside > 0 else max(dx, dy))
    return out
