"""The ROS bridge's added latency per hop (ROS → HLA → ROS), ROS 1 beside ROS 2, each against its own floor (the
same trip through a plain relay node): bench/ros_hop.py. Writes build/bench/ros-bridge.json; the figures are
quoted in docs/ros-bridge.md beside the command."""

from __future__ import annotations

import json
import shutil
import statistics

import pytest

from hlacore.federates.ros_bridge import ros2_env

from .outputs import ROOT
from .ros_hop import measure

COUNT = 1000


@pytest.mark.parametrize("version", [1, 2])
def test_ros_bridge_hop(version: int) -> None:
    if version == 1 and not shutil.which("roscore"):
        pytest.skip("ROS 1 is not installed (./scripts/install-ros.sh)")
    if version == 2 and not ros2_env.installed():
        pytest.skip(f"ROS 2 is not installed ({ros2_env.INSTALL_COMMAND})")
    result = measure(version, COUNT)
    assert len(result["floor"]) == len(result["bridged"]) == COUNT - COUNT // 10
    out = ROOT / "build" / "bench" / "ros-bridge.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    saved = json.loads(out.read_text()) if out.exists() else {}
    saved[f"ros{version}"] = {key: result[key] for key in ("floor_median", "bridged_median", "added")} | {
        "floor_p99": statistics.quantiles(result["floor"], n=100)[98],
        "bridged_p99": statistics.quantiles(result["bridged"], n=100)[98]}
    out.write_text(json.dumps(saved, indent=1))
    print(f"ROS {version}: floor {result['floor_median'] * 1e3:.3f} ms, via HLA {result['bridged_median'] * 1e3:.3f} ms,"
          f" added {result['added'] * 1e3:.3f} ms per hop")
