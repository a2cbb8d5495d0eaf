"""The package type-checks: mypy over python/hlacore (settings in pyproject.toml), with the compiled
module's stub python/hlacore/_core.pyi, finds nothing."""

from __future__ import annotations

import subprocess
import sys

from support import ROOT


def test_mypy_finds_no_error() -> None:
    done = subprocess.run([sys.executable, "-m", "mypy", "--no-incremental"], cwd=ROOT, capture_output=True,
                          text=True, timeout=600, stdin=subprocess.DEVNULL)
    assert done.returncode == 0, done.stdout + done.stderr
