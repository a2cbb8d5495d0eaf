"""The robot's decision: which motor commands take it from one cell to the next (no odometry).

The controller keeps a believed heading in quarter turns (0 faces the first coordinate's growth, 1 the
second's, 2 and 3 the opposite ones) and believes every command did exactly what it should: this is the
paper's robot without accurate odometry, whose believed and real trajectories drift apart when it is
miscalibrated.
"""

from __future__ import annotations

from .navigation import Cell

__all__ = ["QUARTER", "commands_for_move", "heading_degrees"]

#: The unit move of each quarter-turn heading.
QUARTER: dict[int, Cell] = {0: (1, 0), 1: (0, 1), 2: (-1, 0), 3: (0, -1)}


def heading_degrees(quarter: int) -> float:
    """The heading in degrees of a quarter-turn heading."""
    return 90.0 * (quarter % 4)


def commands_for_move(heading: int, here: Cell, there: Cell) -> tuple[list[str], int]:
    """Commands to go from ``here`` to the neighbouring ``there`` facing ``heading``, and the new heading.

    Facing the move: ``goFront``; a quarter turn away: ``turnLeft``/``turnRight`` then ``goFront``; facing
    away: ``goBack`` (the heading is kept). Staying: no command. Raises ValueError for a non-neighbour.
    """
    move = (there[0] - here[0], there[1] - here[1])
    if move == (0, 0):
        return [], heading
    wanted = next((q for q, m in QUARTER.items() if m == move), None)
    if wanted is None:
        raise ValueError(f"{here} -> {there} is not a 4-connected move")
    turn = (wanted - heading) % 4
    if turn == 0:
        return ["goFront"], heading
    if turn == 1:
        return ["turnLeft", "goFront"], wanted
    if turn == 3:
        return ["turnRight", "goFront"], wanted
    return ["goBack"], heading
