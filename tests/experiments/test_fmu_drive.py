"""An FMU in the loop: ``python -m hlacore.experiments.fmu_drive`` compiles the waypoint controller FMU (its C
sources in the package), runs it against the robot world through a real rtig, and writes its trace and plot.
The command's own checks (every waypoint reached in order, the same path as the loop run without HLA, no
collision) must pass; the test reads its JSON summary, CSV and PNG, and checks the controller's commands in
the trace against the FMU stepped here by FMPy on the poses the trace holds."""

from __future__ import annotations

import csv
import json
import pathlib
import subprocess
import sys

import pytest

from hlacore.experiments.fmu_drive.run import SOURCES, STEP, WAYPOINTS
from hlacore.fmu import FmuModel
from hlacore.fmu.build import build_fmu

STEPS = 220  # the robot reaches the last waypoint in about 20 s


def test_the_command_drives_the_robot_through_the_waypoints(rtig: object, tmp_path: pathlib.Path) -> None:
    done = subprocess.run([sys.executable, "-m", "hlacore.experiments.fmu_drive", str(tmp_path),
                           "--rtig", str(rtig.address), "--steps", str(STEPS)],  # type: ignore[attr-defined]
                          capture_output=True, text=True, timeout=300, stdin=subprocess.DEVNULL)
    assert done.returncode == 0, done.stdout + done.stderr
    summary = json.loads(done.stdout.strip().splitlines()[-1])
    assert "FAIL" not in done.stdout
    assert all(when is not None for when in summary["reached"])
    assert summary["reached"] == sorted(summary["reached"])
    assert summary["vs_same_loop"] <= 1e-9 and not summary["stalled"]
    assert 0.0 < summary["vs_ideal"] < 0.5  # the loop's two steps of delay show, and stay small
    assert (tmp_path / "fmu-drive.png").read_bytes().startswith(b"\x89PNG")

    with open(tmp_path / "fmu-drive-trace.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == STEPS + 1
    assert [float(r["time"]) for r in rows] == pytest.approx([k * STEP for k in range(STEPS + 1)])
    end = rows[-1]
    assert (float(end["x"]), float(end["y"])) == pytest.approx(WAYPOINTS[-1], abs=0.1)
    # The commands in the trace are the controller's on the pose it held: the world's of the step before.
    instance = FmuModel(build_fmu(SOURCES, tmp_path / "fmu")).instantiate(0.0)
    try:
        for k in range(STEPS):
            held = rows[max(0, k - 1)]
            instance.set({name: float(held[name]) for name in ("x", "y", "theta")})
            out = instance.do_step(k * STEP, STEP, ["v", "w"])
            assert (float(rows[k]["v"]), float(rows[k]["w"])) == (out["v"], out["w"]), f"step {k}"
    finally:
        instance.close()
