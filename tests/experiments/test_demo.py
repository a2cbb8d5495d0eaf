"""The README's main job: `python -m hlacore.experiments.robot_in_the_loop` runs the robot A* experiment with no configuration."""

import pathlib
import re
import subprocess
import sys


def test_demo_runs_the_experiment_with_no_configuration(tmp_path: pathlib.Path):
    """No option: in-process gateway, calibrated robot on the paper's grid; names its output folder."""
    done = subprocess.run([sys.executable, "-m", "hlacore.experiments.robot_in_the_loop"], capture_output=True, text=True, timeout=110,
                          cwd=tmp_path, stdin=subprocess.DEVNULL)
    assert done.returncode == 0, done.stdout + done.stderr
    out = done.stdout
    assert "(in-process); calibrated robot, stepped mode, 15 cycles" in out
    assert len(re.findall(r"^cycle +\d+ .* ok$", out, re.M)) == 15
    folder = re.search(r"output in (\S+)", out)
    assert folder is not None
    written = {p.name for p in (tmp_path / folder.group(1)).iterdir()}
    assert {"scenario.txt", "robot.log", "trace.csv", "delays.md", "gateway-trace.csv"} <= written
    for row in ("t_cycle^emb", "C_RTI^emb", "t_cycle^RTI", "C_PT^RTI", "t_cycle^DE", "d_RT"):
        assert f"| {row} |" in out
    assert out.rstrip().endswith("experiment finished: checker passed")
