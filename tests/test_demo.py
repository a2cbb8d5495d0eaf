"""The README's main job: the two-federate demo on the in-process gateway."""

import subprocess
import sys


def test_demo_runs_and_every_message_arrives():
    """python -m hlacore.demo exchanges a sync point, three updates, a command and a removal."""
    done = subprocess.run([sys.executable, "-m", "hlacore.demo"], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    out = done.stdout
    assert "federation synchronized at 'ReadyToRun'" in out
    assert out.count("reflected location") == 3
    assert "received command 'stop'" in out
    assert out.rstrip().endswith("demo finished: every message arrived")
