"""The display: one text line per checked cycle."""

from __future__ import annotations

from typing import Callable

from hlacore.federates.de import Actor

from .checker import Verdict

__all__ = ["Display", "format_verdict"]


def format_verdict(verdict: Verdict, precision: float) -> str:
    """``cycle   3  t=3.50 (due 3.50)  robot (0, 3)  reference (0, 3)  ok`` and the errors found."""
    arrival = "   --" if verdict.arrival is None else f"{verdict.arrival:5.2f}"
    actual = "missing" if verdict.actual is None else str(verdict.actual)
    errors = [e for e, bad in (("VALUE ERROR", verdict.value_error),
                               ("TIME ERROR", verdict.time_error(precision))) if bad]
    return (f"cycle {verdict.cycle:3d}  t={arrival} (due {verdict.expected_time:5.2f})  robot {actual:<8}  "
            f"reference {str(verdict.expected):<8}  {' '.join(errors) or 'ok'}")


class Display(Actor):
    """Writes :func:`format_verdict` of each :class:`Verdict` on ``input`` with ``write`` (default print)."""

    def __init__(self, name: str, precision: float, write: Callable[[str], None] = print) -> None:
        super().__init__(name)
        self.precision = precision
        self.write = write
        self.input = self.add_input("input")

    def fire(self) -> None:
        """Write each verdict on ``input``."""
        for verdict in self.input.tokens:
            self.write(format_verdict(verdict, self.precision))
