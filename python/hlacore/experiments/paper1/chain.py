"""Paper 1 with paper 1's architecture: the DE-engine controller federate commands a stageros-style world
through the RTI, the ROS bridge and ROS topics (ros-ptolemy-hla-iess2015, Fig. 1 and 4):

    DE federate (Ptolemy's role)  <->  RTI  <->  ROS bridge (federate + ROS node)  <->  ROS  <->  stage node

Three processes besides roscore, the gateway and this one, each started here and ended by pid:

* ``python -m hlacore.federates.ros_bridge.stage_node paper1.world`` — the world as a ROS node stepping on
  ``/clock`` (Stage's role);
* ``python -m hlacore.experiments.paper1.de_controller`` — the controller federate (the avatar's go / slow /
  stop "Control" actor and the obstacles' driver on the DE engine);
* ``python -m hlacore.federates.ros_bridge --world-node paper1.world --clock --await-state ...`` — the
  bridge: each grant ``G`` on ``/clock``, the node's state of ``G`` back as ``WorldRobot`` updates stamped
  ``G + L``, the ``cmd_vel`` interactions as Twists on ``/<robot>/cmd_vel``.

The loop's delays are those of ``paper1.hla`` (the state of ``G`` is read at ``G + L``, the command acts
from ``G + 2L``), so the robots' poses are those of the RTI-only run.
"""

from __future__ import annotations

import contextlib
import csv
import json
import math
import os
import pathlib
import re
from dataclasses import dataclass, field
from typing import Any, Optional

import hlacore.rti as rti
from hlacore.federates.robot_world import FEDERATION, FOM_PATH, World, render
from hlacore.federates.robot_world.world import Pose
from hlacore.federates.ros_bridge.children import Children

from . import scenario as paper1
from .checks import Result, check, held_back

TRACE = "paper1-de-trace.csv"
SNAPSHOT = "paper1-de-snapshot.png"
PLOT = "paper1-de-trajectories.png"


@dataclass(frozen=True)
class Placement:
    """Where one of the chain's processes runs: ``prefix`` runs its command in place on another host (``ip
    netns exec HOST``), ``rtig`` is the gateway's address from there (None: the run's), ``env`` its ROS
    variables there (``ROS_IP``, ``ROS_MASTER_URI``)."""

    prefix: tuple[str, ...] = ()
    rtig: Optional[str] = None
    env: dict[str, str] = field(default_factory=dict)


ROLES = ("world", "controller", "bridge")


@dataclass
class ChainResult(Result):
    """A :class:`~.checks.Result` from the stage node's ticks, plus the DE federate's view."""

    control: list[tuple[float, float, float]] = field(default_factory=list)  # (DE time, distance, speed)
    de_grants: int = 0
    late_states: int = 0
    late_acks: int = 0
    bridge: str = ""  #: the bridge's last line
    late: list[str] = field(default_factory=list)  #: the bridge's lines about late states or acknowledgements
    ros: Optional[int] = None  #: the ROS between the bridge and the world node (None: the children's choice)

    def summary(self) -> dict[str, Any]:
        """The checks' summary, plus the DE controller's grants, late states and acknowledgements, the
        bridge's lines about them and the number of avatar commands."""
        out = super().summary()
        out.update(controller="de", de_grants=self.de_grants, late_states=self.late_states,
                   late_acks=self.late_acks, late=self.late,
                   avatar_commands=len(self.control), ros=self.ros)
        return out


def run(address: str, outdir: str, duration: float = 30.0, period: float = 0.1, timeout: float = 60.0,
        state_timeout: float = 5.0, hosts: Optional[dict[str, Placement]] = None,
        ros: Optional[int] = None, record_ros: Optional[str] = None) -> ChainResult:
    """Play the scenario on the gateway at ``address`` with the ROS master of ``$ROS_MASTER_URI`` (``ros=1``)
    or over ROS 2's DDS (``ros=2``; None: the children find the ROS, ``ros_bridge.versions.detect``); the
    children's files (world file, summaries, snapshot) go to ``outdir``; ``record_ros``: an MCAP file where the
    bridge writes every ROS message it bridges (``--record-ros``). ``hosts`` places the stage node
    ("world"), the DE federate ("controller") and the bridge each on a host of its own (docs/networking.md);
    ``outdir`` must then be readable and writable from every host (namespaces share the file system)."""
    unknown = set(hosts or {}) - set(ROLES)
    if unknown:
        raise ValueError(f"unknown roles {sorted(unknown)}: the chain's are {ROLES}")
    place = {role: (hosts or {}).get(role, Placement()) for role in ROLES}
    out = pathlib.Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    world_file = out / "paper1.world"
    world_file.write_text(paper1.WORLD)
    stage_json, de_json = out / "stage-node.json", out / "de-federate.json"
    for stale in (stage_json, de_json):
        stale.unlink(missing_ok=True)
    creator = rti.RTIAmbassador(address)
    creator.createFederationExecution(FEDERATION, str(FOM_PATH))
    result = ChainResult()
    result.ros = ros
    which = [] if ros is None else ["--ros", str(ros)]  # the stage node's and the bridge's
    try:
        with Children(dict(os.environ)) as kids:
            world, control, bridge_host = place["world"], place["controller"], place["bridge"]
            stage = kids.start("stage node", ["-m", "hlacore.federates.ros_bridge.stage_node", str(world_file),
                                              *which, "--summary", str(stage_json), "--snapshot", str(out / SNAPSHOT)],
                               world.prefix, world.env)
            stage.wait_for("stage_node ready", timeout)
            de = kids.start("DE federate", ["-m", "hlacore.experiments.paper1.de_controller",
                                            "--rtig", control.rtig or address, "--duration", repr(duration),
                                            "--period", repr(period), "--timeout", repr(timeout),
                                            "--out", str(de_json)], control.prefix, control.env)
            de.wait_for("paper1_de joined", timeout)  # regulating before the bridge can advance
            bridge = kids.start("bridge", ["-m", "hlacore.federates.ros_bridge", *which,
                                           "--rtig", bridge_host.rtig or address, "--world-node", str(world_file),
                                           "--acks", "--clock", "--period", repr(period),
                                           "--await-state", repr(state_timeout), "--wait-connections",
                                           repr(timeout), "--until", repr(duration),
                                           *(["--record-ros", record_ros] if record_ros else [])],
                                bridge_host.prefix, bridge_host.env)
            bridge.wait_for("ros_bridge ready", timeout)
            de.wait_for("paper1_de ready", timeout)
            cycles = math.ceil(duration / period)
            result.bridge = bridge.wait_for("ros_bridge stopped", timeout + cycles * state_timeout)
            result.late = [line for line in bridge.seen if line.startswith("ros_bridge: late")]
            for child in (bridge, de):
                if child.wait(timeout) != 0:
                    raise RuntimeError(child.report(f"exited with status {child.proc.returncode}"))
            if stage.stop() != 0:
                raise RuntimeError(stage.report(f"exited with status {stage.proc.returncode}"))
    except BaseException:
        with contextlib.suppress(Exception):  # a killed child may not have been dropped yet: keep the cause
            creator.destroyFederationExecution(FEDERATION)
        raise
    creator.destroyFederationExecution(FEDERATION)
    stage_summary = json.loads(stage_json.read_text())
    de_summary = json.loads(de_json.read_text())
    result.times = list(stage_summary["times"])
    result.poses = [{n: Pose(*p) for n, p in poses.items()} for poses in stage_summary["poses"]]
    result.stall_steps = dict(stage_summary["stall_steps"])
    result.sent = int(de_summary["sent"])
    result.de_grants = int(de_summary["grants"])
    result.control = [tuple(c) for c in de_summary["control"]]  # type: ignore[misc]
    late = re.search(r"(\d+) late states, (\d+) late acks", result.bridge)
    result.late_states = int(late.group(1)) if late else -1
    result.late_acks = int(late.group(2)) if late else -1
    result.checks = check(result)
    return result


def write_outputs(result: ChainResult, directory: str, period: float = 0.1) -> list[str]:
    """The trace (CSV per stage tick: time, the distance the controller read from that state and the speed
    it commanded, every robot's x and y) and, with matplotlib, the trajectory plot; the snapshot was
    written by the stage node. Returns the files written."""
    out = pathlib.Path(directory)
    out.mkdir(parents=True, exist_ok=True)
    world = World(paper1.world_spec())
    names = [r.name for r in world.robots]
    by_state = {round(t / period) - 1: (d, v) for t, d, v in result.control}  # read at G + L: state of G
    with open(out / TRACE, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["time", "distance", "avatar_speed"] + [f"{n}_{c}" for n in names for c in "xy"])
        for t, poses in zip(result.times, result.poses):
            d, v = by_state.get(round(t / period), ("", ""))
            writer.writerow([repr(t), repr(d), repr(v)] + [repr(c) for n in names for c in (poses[n].x, poses[n].y)])
    written = [str(out / TRACE)]
    if (out / SNAPSHOT).exists():
        written.append(str(out / SNAPSHOT))
    try:
        written.append(str(render.plot_trajectories(world, result.poses, out / PLOT,
                                                    title="paper 1: DE controller through ROS",
                                                    marks={"avatar held back": held_back(result.poses)})))
    except ImportError as exc:
        print(f"no trajectory plot: {exc}")
    return written


def compare_with_rti_only(result: ChainResult, rti_poses: list[dict[str, Pose]]) -> Optional[float]:
    """The largest difference in x or y between the chain's poses and an RTI-only run's at the same grants
    (None when the runs have different lengths)."""
    if len(rti_poses) != len(result.poses):
        return None
    return max((abs(a[n].x - b[n].x) + abs(a[n].y - b[n].y) for a, b in zip(result.poses, rti_poses) for n in a),
               default=0.0)
