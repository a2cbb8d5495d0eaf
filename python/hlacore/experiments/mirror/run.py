"""Paper 2 §6.2 in one run: the world federate (the mirror and the ROS robot) and the ROS bridge in this
process, the "real" robot (robot driver federate + simulated device) and the ROS robot's node in their own
processes, the reference computed; then the trajectories compared.

Threads here: the world federate advances on a thread of its own; the bridge spins on the calling thread
(it waits each grant for the node's answer: a lockstep through ROS). The robot federate is regulating and
constrained with a 0.5 s cycle, so the world (period 0.1 s) runs in lockstep with it too.
"""

from __future__ import annotations

import json
import subprocess
import sys
import threading
from dataclasses import dataclass, field
from typing import Any, Optional

import hlacore.rti as rti
from hlacore.federates.robot_driver.avoid import AvoidParams
from hlacore.federates.robot_world import FEDERATION, FOM_PATH, World, WorldFederate
from hlacore.federates.robot_world.world import Pose

from . import metrics
from .reference import reference_trajectory
from .scenario import BOX_SIZE, BOX_X, CLEAR, HALF, LANES, MIRROR, ROSBOT, world_spec

PERIOD = 0.1  #: the world's and the bridge's period and lookahead, s
DT = 0.01  #: the world's physics step, s
XY = tuple[float, float]


@dataclass
class Result:
    """Everything a run recorded, and the figures computed from it."""

    corrected: bool
    defective_wheel: float
    mirror_from: str
    cycle: float
    reference: list[tuple[float, tuple[float, float, float]]] = field(default_factory=list)
    real: list[dict[str, Any]] = field(default_factory=list)  #: the robot's cycle records (JSON)
    world: list[tuple[float, dict[str, Pose]]] = field(default_factory=list)  #: (grant, poses) per grant
    stall_steps: dict[str, int] = field(default_factory=dict)
    node: dict[str, Any] = field(default_factory=dict)  #: the ROS node's summary
    late_cycles: int = 0  #: bridge grants after which the node's answer came too late
    final_world: Optional[World] = None

    def path(self, who: str) -> list[XY]:
        """The xy path of ``reference``, ``real``, ``mirror`` or ``rosbot`` (the ROS robot moved onto the
        mirror's lane, so that every path compares with the reference)."""
        if who == "reference":
            return [(p[0], p[1]) for _, p in self.reference]
        if who == "real":
            points = [(r["pose"][0], r["pose"][1]) for r in self.real]
            return points + [(self.real[-1]["after"][0], self.real[-1]["after"][1])] if self.real else points
        shift = LANES[MIRROR] - LANES[who]
        return [(poses[who].x, poses[who].y + shift) for _, poses in self.world]

    def figures(self) -> dict[str, Any]:
        """The comparison (m): ``vs_reference``, how far the path strays from the reference path at worst (a
        path that is only late, shorter, still follows it); ``hausdorff``, the symmetric distance (a late
        path counts too); the box clearance from the robot's centre (more than the robot's half diagonal
        0.233 m means no contact: ``touched_box`` otherwise); ``passed_box``, ended beyond the box without
        touching it; where each ended; stalls; the ROS cycles answered late."""
        ref = self.path("reference")
        box = (BOX_X, LANES[MIRROR])
        out: dict[str, Any] = {}
        for who in ("real", "mirror", "rosbot"):
            p = self.path(who)
            clearance = metrics.box_clearance(p, box, BOX_SIZE)
            out[who] = {"vs_reference": metrics.deviation(p, ref), "hausdorff": metrics.hausdorff(p, ref),
                        "box_clearance": clearance, "end": [p[-1][0], p[-1][1]], "touched_box": clearance <= CLEAR,
                        "passed_box": p[-1][0] > BOX_X + BOX_SIZE / 2 + HALF and clearance > CLEAR}
        out["mirror"]["vs_real"] = metrics.hausdorff(self.path("mirror"), self.path("real"))
        out["real"]["avoidances"] = self.real[-1]["avoidances"] if self.real else 0
        out["rosbot"]["avoidances"] = self.node.get("avoidances")
        out["reference"] = {"end": list(ref[-1])}
        out["stall_steps"] = self.stall_steps
        out["late_cycles"] = self.late_cycles
        return out

    def summary(self) -> dict[str, Any]:
        """The JSON summary the command prints last."""
        return {"corrected": self.corrected, "defective_wheel": self.defective_wheel,
                "mirror_from": self.mirror_from, "cycles": len(self.real), "grants": len(self.world),
                **self.figures()}


class _Lines:
    """A child's stdout collected on a thread, for bounded waits on a line."""

    def __init__(self, proc: "subprocess.Popen[str]") -> None:
        self.proc = proc
        self.lines: list[str] = []
        self._cond = threading.Condition()
        self._thread = threading.Thread(target=self._read, daemon=True)
        self._thread.start()

    def _read(self) -> None:
        assert self.proc.stdout is not None
        for line in self.proc.stdout:
            with self._cond:
                self.lines.append(line.rstrip("\n"))
                self._cond.notify_all()

    def wait_for(self, text: str, timeout: float) -> None:
        """Wait until the process has printed the line ``text``; TimeoutError after ``timeout`` seconds,
        RuntimeError if the process ends first."""
        with self._cond:
            if not self._cond.wait_for(lambda: text in self.lines or self.proc.poll() is not None, timeout):
                raise TimeoutError(f"no {text!r} within {timeout} s; saw {self.lines[-20:]}")
            if text not in self.lines:
                raise RuntimeError(f"the process ended ({self.proc.poll()}) before {text!r}: {self.lines[-20:]}")

    def finish(self, timeout: float = 10.0) -> list[str]:
        """Wait up to ``timeout`` seconds for the end of the output; return every line read."""
        self._thread.join(timeout)
        return self.lines


def _spawn(args: list[str]) -> "tuple[subprocess.Popen[str], _Lines]":
    proc = subprocess.Popen([sys.executable, *args], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            stdin=subprocess.DEVNULL, text=True)
    return proc, _Lines(proc)


def run(address: str, corrected: bool = False, defective_wheel: float = 0.0, cycles: int = 50,
        mirror_from: str = "commands", params: Optional[AvoidParams] = None, start_timeout: float = 60.0,
        cycle_timeout: float = 30.0) -> Result:
    """One run on the gateway at ``address`` with the ROS master of ``$ROS_MASTER_URI`` (the bridge is this
    process's ROS node: call once per process)."""
    from hlacore.federates.ros_bridge import OdometryOut, RosBridge, stage_mappings
    from hlacore.federates.ros_bridge.children import stop_process
    from hlacore.federates.ros_bridge.runner import WorldThread, wait_wired

    params = params or AvoidParams()
    duration = (cycles + 1) * params.cycle  # the world carries out the last command too
    result = Result(corrected, defective_wheel, mirror_from, params.cycle)
    result.reference = reference_trajectory(cycles, corrected, params, DT)
    spec = world_spec()
    sensor = spec.robots[[r.name for r in spec.robots].index(ROSBOT)].sensors[0]
    creator = rti.RTIAmbassador(address)
    creator.createFederationExecution(FEDERATION, str(FOM_PATH))
    # the watchdog stops a robot whose commands stop (a dead controller); commands come every cycle
    world = WorldFederate.join(World(spec, dt=DT, watchdog=2 * params.cycle), address, period=PERIOD,
                               lookahead=PERIOD)
    mappings = stage_mappings(ROSBOT, fov=sensor.fov, range_min=sensor.range_min, range_max=sensor.range_max)
    mappings.append(OdometryOut("real", "/real/odom", "pose", "real/odom"))  # the real robot's odometry on ROS
    bridge = RosBridge(mappings, address, period=PERIOD, clock=True, await_inputs=5.0)
    node = robot = None
    try:
        bridge.start()
        flags = ["--corrected"] if corrected else []
        node, node_out = _spawn(["-m", "hlacore.experiments.mirror.node", "--robot", ROSBOT, "--cycle",
                                 repr(params.cycle), "--lookahead", repr(PERIOD), *flags])
        robot, robot_out = _spawn(["-m", "hlacore.federates.robot_driver", "--rtig", address, "--mirror", MIRROR,
                                   "--cycles", str(cycles), "--cycle", repr(params.cycle), "--defective-wheel",
                                   repr(defective_wheel), "--mirror-from", mirror_from, *flags])
        robot_out.wait_for("robot ready", start_timeout)
        wired = [f"/{ROSBOT}/odom", f"/{ROSBOT}/range", f"/{ROSBOT}/cmd_vel"]
        if not wait_wired(bridge, wired, node, start_timeout):
            raise RuntimeError(f"the ROS node did not connect: {bridge.connections()}; {node_out.lines}")
        finished = threading.Event()
        ros_node = node

        def watch_node() -> None:
            # a dead node would leave the bridge waiting ``await_inputs`` at every grant: end the run instead
            while not finished.wait(0.2):
                if ros_node.poll() is not None:
                    world_thread.fail(RuntimeError(f"the ROS node ended early (status {ros_node.returncode}): "
                                                   f"{node_out.lines[-20:]}"))
                    return

        world_thread = WorldThread(world, duration, cycle_timeout, bridge)
        threading.Thread(target=watch_node, name="watch-node", daemon=True).start()
        bridge.spin(until=duration, cycle_timeout=0.05)
        finished.set()
        if world_thread.failure:
            bridge.close()  # resigned: the world's remaining grants no longer wait for the bridge
        world_thread.join()
        if robot.wait(cycle_timeout) != 0:
            raise RuntimeError(f"the robot federate failed: {robot_out.finish()[-20:]}")
        result.real = [json.loads(line) for line in robot_out.finish() if line.startswith('{"cycle"')]
        stop_process(node)
        result.node = next((json.loads(line) for line in reversed(node_out.finish()) if line.startswith("{")), {})
    finally:
        for proc in (robot, node):
            if proc is not None:
                stop_process(proc)
                if proc.stdout is not None:
                    proc.stdout.close()
        result.late_cycles = bridge.late_cycles
        if bridge.rtia is not None:
            bridge.close()
        world.resign()
        creator.destroyFederationExecution(FEDERATION)
    result.world = list(world.history)
    result.stall_steps = {r.name: r.stall_steps for r in world.world.robots}
    result.final_world = world.world
    return result
