"""Every Python block of the README and of docs/pyhla.md runs as written, from the repository's root."""

from __future__ import annotations

import re
import subprocess
import sys

import pytest

from support import ROOT

BLOCKS = [block for page in ("README.md", "docs/pyhla.md")
          for block in re.findall(r"```python\n(.*?)```", (ROOT / page).read_text(), re.S)]


def test_the_readme_has_python_blocks() -> None:
    assert len(BLOCKS) >= 3


@pytest.mark.parametrize("block", BLOCKS, ids=[f"block{i + 1}" for i in range(len(BLOCKS))])
def test_readme_python_block_runs(block: str) -> None:
    done = subprocess.run([sys.executable, "-c", block], cwd=ROOT, capture_output=True, text=True, timeout=60,
                          stdin=subprocess.DEVNULL)
    assert done.returncode == 0, done.stdout + done.stderr
