"""Grid scenarios and A* navigation (4-connected), shared by the robot and the testbench's reference model.

A cell is a pair ``(a, b)`` of grid coordinates, written as in the paper (``(0, 0)`` ... ``(4, 4)``); on the
floor, cell ``(a, b)`` has its centre at ``(a * CELL, b * CELL)`` metres. Moves are the four unit steps;
A* uses the Manhattan heuristic, a closed set and a FIFO tie-break on ``(f, insertion order)`` with the
neighbour order ``(1,0), (0,1), (-1,0), (0,-1)`` (the order that also reproduces the paper's path when
walls are discovered on line; with the full map the shortest path is unique on the paper's grid).

A :class:`Scenario` reads from a small text file (the testbench's stimulus)::

    # comment
    grid 5x5
    walls (1,0) (1,1) (1,2) (2,4) (3,1) (3,2) (3,3)
    start 0 0
    goal 4 4
"""

from __future__ import annotations

import heapq
import pathlib
import re
from dataclasses import dataclass, field
from typing import Iterator, Optional, Union

__all__ = ["CELL", "Cell", "Scenario", "astar", "mission", "PAPER_5X5", "SCENARIO_6X6", "scenario_named"]

#: Side of a cell, metres (the paper's 33 cm squares).
CELL = 0.33

Cell = tuple[int, int]

#: The four moves, in the order A* generates successors.
MOVES: tuple[Cell, ...] = ((1, 0), (0, 1), (-1, 0), (0, -1))


@dataclass(frozen=True)
class Scenario:
    """A grid of ``width`` x ``height`` cells with ``walls``, a ``start`` and a ``goal`` cell."""

    width: int
    height: int
    walls: frozenset[Cell] = field(default_factory=frozenset)
    start: Cell = (0, 0)
    goal: Cell = (0, 0)

    def free(self, cell: Cell) -> bool:
        """True when ``cell`` is on the grid and not a wall."""
        a, b = cell
        return 0 <= a < self.width and 0 <= b < self.height and cell not in self.walls

    def to_text(self) -> str:
        """The file form (see the module docstring)."""
        walls = " ".join(f"({a},{b})" for a, b in sorted(self.walls))
        return (f"grid {self.width}x{self.height}\nwalls {walls}\n"
                f"start {self.start[0]} {self.start[1]}\ngoal {self.goal[0]} {self.goal[1]}\n")

    @classmethod
    def parse(cls, text: str) -> "Scenario":
        """Read the file form; raises ValueError on an unknown line or a missing ``grid``."""
        width = height = None
        walls: set[Cell] = set()
        start: Cell = (0, 0)
        goal: Optional[Cell] = None
        for number, raw in enumerate(text.splitlines(), 1):
            line = raw.split("#", 1)[0].strip()
            if not line:
                continue
            key, _, rest = line.partition(" ")
            numbers = [int(n) for n in re.findall(r"-?\d+", rest)]
            if key == "grid" and len(numbers) == 2:
                width, height = numbers
            elif key == "walls" and len(numbers) % 2 == 0:
                walls.update(zip(numbers[0::2], numbers[1::2]))
            elif key == "start" and len(numbers) == 2:
                start = (numbers[0], numbers[1])
            elif key == "goal" and len(numbers) == 2:
                goal = (numbers[0], numbers[1])
            else:
                raise ValueError(f"scenario line {number}: cannot read {raw!r}")
        if width is None or height is None:
            raise ValueError("scenario: no 'grid WxH' line")
        scenario = cls(width, height, frozenset(walls), start, goal if goal is not None else start)
        for name, cell in (("start", scenario.start), ("goal", scenario.goal)):
            if not scenario.free(cell):
                raise ValueError(f"scenario: {name} {cell} is a wall or off the grid")
        return scenario

    @classmethod
    def load(cls, path: Union[str, pathlib.Path]) -> "Scenario":
        """:meth:`parse` the file at ``path``."""
        return cls.parse(pathlib.Path(path).read_text())


#: The paper's Fig. 7/9 grid (testing-rtes-hla-2016 §6.1).
PAPER_5X5 = Scenario(5, 5, frozenset({(1, 0), (1, 1), (1, 2), (2, 4), (3, 1), (3, 2), (3, 3)}), (0, 0), (4, 4))

#: A 6 x 6 scenario of ours: the paper's Figs. 10/11 give theirs only as pictures.
SCENARIO_6X6 = Scenario(
    6, 6, frozenset({(1, 1), (1, 2), (1, 3), (1, 4), (3, 0), (3, 1), (3, 2), (3, 4), (3, 5), (4, 4)}), (0, 0), (5, 5)
)


def scenario_named(name: str) -> Scenario:
    """``"5x5"`` (the paper's) or ``"6x6"`` (ours); raises ValueError otherwise."""
    table = {"5x5": PAPER_5X5, "6x6": SCENARIO_6X6}
    if name not in table:
        raise ValueError(f"unknown grid {name!r}: choose one of {', '.join(table)} or give a scenario file")
    return table[name]


def astar(scenario: Scenario, start: Cell, goal: Cell) -> list[Cell]:
    """The A* path from ``start`` to ``goal``, both included; raises ValueError when there is none."""
    def h(cell: Cell) -> int:
        return abs(cell[0] - goal[0]) + abs(cell[1] - goal[1])

    counter = 0
    frontier: list[tuple[int, int, Cell]] = [(h(start), counter, start)]
    came_from: dict[Cell, Optional[Cell]] = {start: None}
    cost: dict[Cell, int] = {start: 0}
    closed: set[Cell] = set()
    while frontier:
        _, _, cell = heapq.heappop(frontier)
        if cell == goal:
            path = [cell]
            while came_from[path[-1]] is not None:
                path.append(came_from[path[-1]])  # type: ignore[arg-type]
            return path[::-1]
        if cell in closed:
            continue
        closed.add(cell)
        for da, db in MOVES:
            nxt = (cell[0] + da, cell[1] + db)
            if not scenario.free(nxt) or nxt in closed:
                continue
            g = cost[cell] + 1
            if g < cost.get(nxt, g + 1):
                cost[nxt] = g
                came_from[nxt] = cell
                counter += 1
                heapq.heappush(frontier, (g + h(nxt), counter, nxt))
    raise ValueError(f"no path from {start} to {goal}")


def mission(scenario: Scenario) -> Iterator[Cell]:
    """The cell of each cycle: start, the A* path to the goal, then back and forth (a patrol), for ever.

    Cycle 0 is the start cell; cycle ``k`` is the cell after ``k`` moves. Use ``itertools.islice``.
    """
    here, there = scenario.start, scenario.goal
    yield here
    if here == there:
        while True:
            yield here
    while True:
        for cell in astar(scenario, here, there)[1:]:
            yield cell
        here, there = there, here
