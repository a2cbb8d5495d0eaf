"""What the experiments' commands share: a run stopped by Ctrl-C or a gateway that cannot be reached ends
with one line naming the cause, not a traceback (other errors keep theirs: they are bugs to report)."""

from __future__ import annotations

import sys
from typing import Callable, Optional

from hlacore.exceptions import RTIinternalError


def run_command(prog: str, main: Callable[[], int], outputs: Optional[Callable[[], str]] = None) -> int:
    """``main()``'s exit status; 130 after Ctrl-C, 1 when the gateway is unreachable or lost. ``outputs``
    says where the files written so far are, for the interrupted run's line."""
    try:
        return main()
    except KeyboardInterrupt:
        where = f"; what it wrote so far is in {outputs()}" if outputs else ""
        print(f"{prog}: interrupted{where}", file=sys.stderr)
        return 130
    except RTIinternalError as exc:
        print(f"{prog}: {exc}", file=sys.stderr)
        return 1
