"""The robot's per-cycle report, the value of the FOM's ``robot.location`` attribute (UTF-8 JSON).

Besides the measured cell and pose it carries the robot's wall-clock marks (its ``time.monotonic()``) and
its clock's offset to the gateway's, with which the testbench puts them on one clock for the delay
decomposition, the robot being on another host or not.
"""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass

from .navigation import Cell

__all__ = ["LocationReport", "encode_report", "decode_report", "REPORT_CODEC"]


@dataclass(frozen=True)
class LocationReport:
    """One control cycle of the robot.

    ``cell``: where the position tracker puts the robot after the cycle's commands; ``believed``: where
    the robot thinks it is; ``pose``: x, y (m), heading (deg); ``front``: the front range (m);
    ``t_action``: wall time when the commands were done; ``t_send``: just before the update was sent;
    ``t_cycle``: seconds from the start of the cycle (after the grant) to ``t_send``;
    ``clock_offset`` ± ``clock_uncertainty``: the gateway's clock minus the robot's (seconds,
    ``RTIAmbassador.clock_offset``).
    """

    cycle: int
    cell: Cell
    believed: Cell
    pose: tuple[float, float, float]
    front: float
    commands: tuple[str, ...]
    t_action: float
    t_send: float
    t_cycle: float
    clock_offset: float = 0.0
    clock_uncertainty: float = 0.0


def encode_report(report: LocationReport) -> bytes:
    """The attribute value of ``report``."""
    return json.dumps(asdict(report), separators=(",", ":")).encode("utf-8")


def decode_report(data: bytes) -> LocationReport:
    """The report in an attribute value; raises ValueError when it is not one."""
    raw = json.loads(data.decode("utf-8"))
    try:
        return LocationReport(
            cycle=int(raw["cycle"]),
            cell=(int(raw["cell"][0]), int(raw["cell"][1])),
            believed=(int(raw["believed"][0]), int(raw["believed"][1])),
            pose=(float(raw["pose"][0]), float(raw["pose"][1]), float(raw["pose"][2])),
            front=float(raw["front"]),
            commands=tuple(str(c) for c in raw["commands"]),
            t_action=float(raw["t_action"]),
            t_send=float(raw["t_send"]),
            t_cycle=float(raw["t_cycle"]),
            clock_offset=float(raw.get("clock_offset", 0.0)),
            clock_uncertainty=float(raw.get("clock_uncertainty", 0.0)),
        )
    except (KeyError, TypeError, IndexError) as error:
        raise ValueError(f"not a location report: {error}") from None


#: The codec for the DE engine's publishers and subscribers.
REPORT_CODEC = (encode_report, decode_report)
