"""Pictures of a world: a top-down PNG snapshot (pure Python, no dependency) and a trajectory plot
(matplotlib, imported only when plotting, with a clear error when it is missing)."""

from __future__ import annotations

import math
import pathlib
import struct
import zlib
from dataclasses import dataclass
from typing import Any, Iterable, Mapping, Optional, Sequence, Union

from .world import Pose, World, beam_angles

RGB = tuple[int, int, int]
_NAMED: dict[str, RGB] = {
    "black": (0, 0, 0), "white": (255, 255, 255), "red": (220, 30, 30), "green": (30, 160, 30),
    "blue": (30, 60, 220), "yellow": (230, 200, 0), "orange": (240, 140, 0), "cyan": (0, 190, 190),
    "magenta": (200, 0, 200), "gray": (128, 128, 128), "grey": (128, 128, 128), "dark_gray": (80, 80, 80),
}
BACKGROUND: RGB = (255, 255, 255)
BEAM: RGB = (150, 190, 255)
TRAIL: RGB = (0, 150, 0)


def color(name: str) -> RGB:
    """An RGB triple for a Stage colour name (``grayNN`` is NN% white); unknown names are mid grey."""
    key = name.strip().lower()
    if key in _NAMED:
        return _NAMED[key]
    for prefix in ("gray", "grey"):
        if key.startswith(prefix) and key[len(prefix):].isdigit():
            level = round(255 * min(100, int(key[len(prefix):])) / 100)
            return (level, level, level)
    return (128, 128, 128)


@dataclass
class Image:
    """An RGB raster whose pixel (0, 0) is the top-left corner; world y points up."""

    width: int
    height: int
    pixels: bytearray
    scale: float  # pixels per metre
    origin: tuple[float, float]  # world coordinates of the top-left corner

    def to_pixel(self, x: float, y: float) -> tuple[int, int]:
        """The pixel (column, row) under world point (x, y)."""
        return (int(math.floor((x - self.origin[0]) * self.scale)),
                int(math.floor((self.origin[1] - y) * self.scale)))

    def get(self, col: int, row: int) -> RGB:
        """The colour of a pixel."""
        i = 3 * (row * self.width + col)
        return (self.pixels[i], self.pixels[i + 1], self.pixels[i + 2])

    def put(self, col: int, row: int, rgb: RGB) -> None:
        """Paint one pixel (ignored outside the image)."""
        if 0 <= col < self.width and 0 <= row < self.height:
            i = 3 * (row * self.width + col)
            self.pixels[i:i + 3] = bytes(rgb)

    def fill_polygon(self, points: Sequence[tuple[float, float]], rgb: RGB) -> None:
        """Fill a convex polygon given in world coordinates (pixel centres inside it are painted)."""
        px = [((x - self.origin[0]) * self.scale, (self.origin[1] - y) * self.scale) for x, y in points]
        c0 = max(0, int(math.floor(min(p[0] for p in px))))
        c1 = min(self.width - 1, int(math.ceil(max(p[0] for p in px))))
        r0 = max(0, int(math.floor(min(p[1] for p in px))))
        r1 = min(self.height - 1, int(math.ceil(max(p[1] for p in px))))
        edges = list(zip(px, px[1:] + px[:1]))
        for row in range(r0, r1 + 1):
            cy = row + 0.5
            for col in range(c0, c1 + 1):
                cx = col + 0.5
                signs = [(bx - ax) * (cy - ay) - (by - ay) * (cx - ax) for (ax, ay), (bx, by) in edges]
                if all(s >= 0 for s in signs) or all(s <= 0 for s in signs):
                    self.put(col, row, rgb)

    def line(self, a: tuple[float, float], b: tuple[float, float], rgb: RGB) -> None:
        """Draw a one-pixel line between world points."""
        (c0, r0), (c1, r1) = self.to_pixel(*a), self.to_pixel(*b)
        n = max(abs(c1 - c0), abs(r1 - r0), 1)
        for i in range(n + 1):
            self.put(round(c0 + (c1 - c0) * i / n), round(r0 + (r1 - r0) * i / n), rgb)

    def to_png(self) -> bytes:
        """Encode as an 8-bit RGB PNG."""
        raw = b"".join(b"\x00" + bytes(self.pixels[3 * self.width * r:3 * self.width * (r + 1)])
                       for r in range(self.height))

        def chunk(kind: bytes, data: bytes) -> bytes:
            return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

        header = struct.pack(">IIBBBBB", self.width, self.height, 8, 2, 0, 0, 0)
        return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(
            b"IEND", b"")


def _bounds(world: World) -> tuple[float, float, float, float]:
    xs: list[float] = []
    ys: list[float] = []
    for shape in world.space.shapes:
        bb = shape.bb
        xs += [bb.left, bb.right]
        ys += [bb.bottom, bb.top]
    if not xs:
        return (-1.0, -1.0, 1.0, 1.0)
    return (min(xs), min(ys), max(xs), max(ys))


def snapshot(world: World, scale: float = 40.0, margin: float = 0.5, beams: bool = True,
             trails: Optional[Mapping[str, Sequence[tuple[float, float]]]] = None) -> Image:
    """Draw the world from above: static boxes, robots in their colours with a white nose line, ranger
    beams (light blue) and optional trails (world points per robot, green)."""
    x0, y0, x1, y1 = _bounds(world)
    for trail in (trails or {}).values():
        for x, y in trail:
            x0, y0, x1, y1 = min(x0, x), min(y0, y), max(x1, x), max(y1, y)
    x0, y0, x1, y1 = x0 - margin, y0 - margin, x1 + margin, y1 + margin
    width, height = max(1, math.ceil((x1 - x0) * scale)), max(1, math.ceil((y1 - y0) * scale))
    image = Image(width, height, bytearray(bytes(BACKGROUND) * (width * height)), scale, (x0, y1))
    for block in world.spec.blocks:
        points = [(float(v.x), float(v.y)) for v in _static_vertices(world, block.pose, block.size)]
        image.fill_polygon(points, color(block.color))
    for trail in (trails or {}).values():
        for a, b in zip(trail, trail[1:]):
            image.line(a, b, TRAIL)
    for robot in world.robots:
        pose = robot.pose
        if beams:
            for start, end in beam_segments(world, robot.name):
                image.line(start, end, BEAM)
        corners = [robot.body.local_to_world(v) for v in robot.shape.get_vertices()]
        image.fill_polygon([(float(p.x), float(p.y)) for p in corners], color(robot.spec.color))
        nose = (pose.x + 0.5 * robot.spec.size[0] * math.cos(pose.theta),
                pose.y + 0.5 * robot.spec.size[0] * math.sin(pose.theta))
        image.line((pose.x, pose.y), nose, (255, 255, 255))
    return image


def _static_vertices(world: World, pose: tuple[float, float, float], size: tuple[float, float]) -> list[Any]:
    import pymunk

    x, y, a = pose
    c, s = math.cos(a), math.sin(a)
    hx, hy = size[0] / 2, size[1] / 2
    return [pymunk.Vec2d(x + c * px - s * py, y + s * px + c * py)
            for px, py in ((-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy))]


def beam_segments(world: World, name: str) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """Each ranger beam of a robot as (start, end) world points, the end at the measured range."""
    robot = world.robot(name)
    pose = robot.pose
    c, s = math.cos(pose.theta), math.sin(pose.theta)
    out = []
    i = 0
    for sensor in robot.spec.sensors:
        sx, sy, sa = sensor.pose
        ox, oy = pose.x + c * sx - s * sy, pose.y + s * sx + c * sy
        for beam in beam_angles(sensor):
            a = pose.theta + sa + beam
            r = robot.ranges[i]
            out.append(((ox, oy), (ox + r * math.cos(a), oy + r * math.sin(a))))
            i += 1
    return out


def write_snapshot(world: World, path: Union[str, pathlib.Path], **options: object) -> pathlib.Path:
    """Write :func:`snapshot` as a PNG file; returns the path."""
    out = pathlib.Path(path)
    out.write_bytes(snapshot(world, **options).to_png())  # type: ignore[arg-type]
    return out


def trajectories(poses: Iterable[Mapping[str, Pose]]) -> dict[str, list[tuple[float, float]]]:
    """The data behind the trajectory plot: each robot's (x, y) points, in order."""
    out: dict[str, list[tuple[float, float]]] = {}
    for sample in poses:
        for name, pose in sample.items():
            out.setdefault(name, []).append((pose.x, pose.y))
    return out


def _pyplot() -> Any:
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as exc:
        raise ImportError(
            "plotting trajectories needs matplotlib: pip install matplotlib (or hlacore[plot])"
        ) from exc
    return plt


def _draw_blocks(ax: Any, world: World, labelled: bool = True) -> None:
    """The world's static boxes in their colours, each name once in the legend ("wall" when unnamed)."""
    seen: set[str] = set()
    for block in world.spec.blocks:
        pts = [(float(v.x), float(v.y)) for v in _static_vertices(world, block.pose, block.size)]
        label = block.name or "wall"
        ax.fill([p[0] for p in pts], [p[1] for p in pts], color=[c / 255 for c in color(block.color)],
                label=label if labelled and label not in seen else None)
        seen.add(label)


def _finish(fig: Any, ax: Any, path: Union[str, pathlib.Path], title: str, handles: Optional[list[Any]] = None
            ) -> pathlib.Path:
    """Axes in metres, the title, the legend beside the plot; written by suffix (PNG or SVG)."""
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.grid(True, alpha=0.3)
    if title:
        ax.set_title(title)
    ax.legend(handles=handles, loc="center left", bbox_to_anchor=(1.02, 0.5), fontsize="small")
    fig.tight_layout()
    out = pathlib.Path(path)
    fig.savefig(out, dpi=100)
    return out


def write_labelled_snapshot(world: World, path: Union[str, pathlib.Path], title: str,
                            trails: Optional[Mapping[str, Sequence[tuple[float, float]]]] = None) -> pathlib.Path:
    """The world from above as a figure for readers: axes in metres, ``title``, and a legend naming every
    box, robot, its trail and the ranger beams (matplotlib). Without matplotlib, :func:`write_snapshot`'s
    raster (no text) and a line saying so. Returns the path."""
    try:
        plt = _pyplot()
    except ImportError as exc:
        print(f"snapshot without labels: {exc}")
        return write_snapshot(world, path, trails=trails)
    fig, ax = plt.subplots(figsize=(7, 5))
    try:
        _draw_blocks(ax, world)
        beams_labelled = False
        for robot in world.robots:
            rgb = [c / 255 for c in color(robot.spec.color)]
            for start, end in beam_segments(world, robot.name):
                ax.plot([start[0], end[0]], [start[1], end[1]], color=[c / 255 for c in BEAM], lw=0.8,
                        label=None if beams_labelled else "ranger beams")
                beams_labelled = True
            trail = (trails or {}).get(robot.name, [])
            if trail:
                ax.plot([p[0] for p in trail], [p[1] for p in trail], ":", color=rgb, label=f"{robot.name} trail")
            corners = [robot.body.local_to_world(v) for v in robot.shape.get_vertices()]
            ax.fill([float(p.x) for p in corners], [float(p.y) for p in corners], color=rgb,
                    label=f"{robot.name} at {world.time:.1f} s")
        return _finish(fig, ax, path, title)
    finally:
        plt.close(fig)


def plot_trajectories(world: World, poses: Iterable[Mapping[str, Pose]], path: Union[str, pathlib.Path],
                      title: str = "", marks: Optional[Mapping[str, Sequence[tuple[float, float]]]] = None
                      ) -> pathlib.Path:
    """Plot every robot's trajectory over the world's static boxes and write it (PNG or SVG by suffix).

    The legend names each robot, the static boxes (by their name, "wall" when unnamed), the start (circle)
    and end (square) of each trajectory, and ``marks``: labelled points to show, such as where a check
    found what it looked for. Axes in metres. Needs matplotlib (ImportError saying so otherwise)."""
    plt = _pyplot()
    from matplotlib.lines import Line2D

    tracks = trajectories(poses)
    fig, ax = plt.subplots(figsize=(7, 5))
    try:
        _draw_blocks(ax, world)
        for robot in world.robots:
            track = tracks.get(robot.name, [])
            if track:
                rgb = [c / 255 for c in color(robot.spec.color)]
                ax.plot([p[0] for p in track], [p[1] for p in track], color=rgb, label=robot.name)
                ax.plot([track[0][0]], [track[0][1]], "o", color=rgb, fillstyle="none")
                ax.plot([track[-1][0]], [track[-1][1]], "s", color=rgb)
        for (label, points), style in zip((marks or {}).items(), ("x", "+", "^", "v")):
            if points:
                ax.plot([p[0] for p in points], [p[1] for p in points], style, color="tab:purple", label=label)
        handles, _ = ax.get_legend_handles_labels()
        handles += [Line2D([], [], marker="o", fillstyle="none", color="0.4", ls="", label="start"),
                    Line2D([], [], marker="s", color="0.4", ls="", label="end")]
        return _finish(fig, ax, path, title, handles)
    finally:
        plt.close(fig)


def animation_frames(poses: Sequence[Mapping[str, Pose]], frames: int) -> list[int]:
    """The sample indices an animation of ``frames`` frames shows: evenly spread, first and last included."""
    if not poses or frames < 1:
        return []
    last = len(poses) - 1
    if frames == 1 or last == 0:
        return [last]
    count = min(frames, last + 1)
    return sorted({round(i * last / (count - 1)) for i in range(count)})


def animate_trajectories(world: World, poses: Sequence[Mapping[str, Pose]], path: Union[str, pathlib.Path],
                         frames: int = 60, fps: int = 10, title: str = "") -> pathlib.Path:
    """Write an animated GIF of the run: each frame shows the trajectories so far and the robots' current
    positions (frames from :func:`animation_frames`). Needs matplotlib (and Pillow, its dependency)."""
    plt = _pyplot()
    from matplotlib.animation import FuncAnimation, PillowWriter

    tracks = trajectories(poses)
    indices = animation_frames(poses, frames)
    fig, ax = plt.subplots(figsize=(7, 5))
    try:
        _draw_blocks(ax, world, labelled=False)
        lines, marks = {}, {}
        for robot in world.robots:
            rgb = [c / 255 for c in color(robot.spec.color)]
            (lines[robot.name],) = ax.plot([], [], color=rgb, label=robot.name)
            (marks[robot.name],) = ax.plot([], [], "s", color=rgb)
        xs = [p[0] for t in tracks.values() for p in t]
        ys = [p[1] for t in tracks.values() for p in t]
        x0, y0, x1, y1 = _bounds(world)
        ax.set_xlim(min([x0, *xs]) - 0.5, max([x1, *xs]) + 0.5)
        ax.set_ylim(min([y0, *ys]) - 0.5, max([y1, *ys]) + 0.5)
        ax.set_aspect("equal")
        ax.legend(loc="best", fontsize="small")

        def draw(frame: int) -> list[Any]:
            k = indices[frame]
            for name, track in tracks.items():
                lines[name].set_data([p[0] for p in track[:k + 1]], [p[1] for p in track[:k + 1]])
                marks[name].set_data([track[k][0]], [track[k][1]])
            ax.set_title(f"{title} (sample {k + 1}/{len(poses)})".strip())
            return [*lines.values(), *marks.values()]

        animation = FuncAnimation(fig, draw, frames=len(indices), blit=False)
        out = pathlib.Path(path)
        animation.save(str(out), writer=PillowWriter(fps=fps))
    finally:
        plt.close(fig)
    return out
