"""Saying a problem once: a bridge that meets the same bad input at every message or grant says so the first
time, counts the rest, and goes on."""

from __future__ import annotations

import sys
from typing import Hashable, TextIO


class Once:
    """Lines ``"<who>: <text>"`` on ``stream`` (default stderr), each key said at most once until
    :meth:`forget`."""

    def __init__(self, who: str, stream: TextIO | None = None) -> None:
        self.who = who
        self.stream = stream
        self.lines: list[str] = []  #: everything said, in order
        self._said: set[Hashable] = set()

    def say(self, key: Hashable, text: str) -> bool:
        """Print ``text`` unless ``key`` was said already; True when printed."""
        if key in self._said:
            return False
        self._said.add(key)
        line = f"{self.who}: {text}"
        self.lines.append(line)
        print(line, file=self.stream or sys.stderr, flush=True)
        return True

    def forget(self, key: Hashable) -> None:
        """Let ``key`` be said again (the problem went away)."""
        self._said.discard(key)
