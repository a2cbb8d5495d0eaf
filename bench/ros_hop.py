"""The ROS bridge's hop: what the HLA path adds to a Twist's trip from a ROS node back to a ROS node, on ROS 1 and
ROS 2 alike (docs/ros-bridge.md, "Performance").

    floor:    ping ──ROS──> relay ──ROS──> ping
    bridged:  ping ──ROS──> bridge (into HLA) ──HLA: gateway──> bridge (out of HLA) ──ROS──> ping

The same ping node (bench/peers/ros_hop.py, one process per role) times each Twist's round trip. The bridged
path replaces the relay by two bridges and the gateway (in this process, reached over a Unix socket), so the
difference of the medians is what one ROS → HLA → ROS hop adds. ROS 1 runs with a roscore of its own on
loopback; ROS 2 inside a network namespace that has only loopback (Fast DDS binds every interface it sees)."""

from __future__ import annotations

import contextlib
import json
import os
import pathlib
import random
import shutil
import statistics
import subprocess
import sys
import tempfile
from typing import Any, Iterator

import hlacore
from hlacore.federates.robot_world import FEDERATION, FOM_PATH
from hlacore.federates.ros_bridge import ros2_env
from hlacore.federates.ros_bridge.children import Children
from hlacore.federates.ros_bridge.master import ros_master
from hlacore import rti

PEER = str(pathlib.Path(__file__).resolve().parent / "peers" / "ros_hop.py")


@contextlib.contextmanager
def _loopback_namespace() -> Iterator[list[str]]:
    name = f"hlacore-hop-{os.getpid()}"
    subprocess.run(["ip", "netns", "add", name], check=True, capture_output=True, timeout=30)
    try:
        subprocess.run(["ip", "-n", name, "link", "set", "lo", "up"], check=True, capture_output=True, timeout=30)
        yield ["ip", "netns", "exec", name]
    finally:
        subprocess.run(["ip", "netns", "delete", name], capture_output=True, timeout=30)


@contextlib.contextmanager
def _ros(version: int, scratch: str) -> Iterator[tuple[dict[str, str], list[str]]]:
    """The environment and the command prefix of ROS ``version``'s processes."""
    if version == 1:
        with ros_master():  # $ROS_MASTER_URI when one answers, else a roscore of its own
            yield dict(os.environ, ROS_IP="127.0.0.1", ROS_HOME=scratch, ROS_LOG_DIR=scratch), []
        return
    env = ros2_env.environment(domain_id=random.randrange(1, 100), log_dir=scratch)
    with _loopback_namespace() as prefix:
        yield dict(env, ROS_HOME=scratch), prefix


def measure(version: int, count: int = 1000) -> dict[str, Any]:
    """The round trips (s) of ``count`` Twists, floor and bridged, on ROS ``version``; and their medians."""
    out: dict[str, Any] = {"ros": version}
    with tempfile.TemporaryDirectory() as scratch, _ros(version, scratch) as (env, prefix):
        env = dict(env, PYTHONUNBUFFERED="1")
        for path in ("floor", "bridged"):
            with contextlib.ExitStack() as stack:
                if path == "floor":
                    kids = stack.enter_context(Children(env))
                    kids.start("relay", [PEER, "relay", "--ros", str(version)], prefix).wait_for("relay ready", 60)
                else:
                    socket = os.path.join(scratch, "rtig.sock")
                    gateway = stack.enter_context(hlacore.Gateway(port=0, unix=socket))
                    creator = rti.RTIAmbassador(str(gateway.unix_address))
                    creator.createFederationExecution(FEDERATION, str(FOM_PATH))
                    stack.callback(creator.destroyFederationExecution, FEDERATION)
                    kids = stack.enter_context(Children(env))  # stopped before the federation is destroyed
                    for role in ("out-of-hla", "into-hla"):
                        kids.start(role, [PEER, role, str(gateway.unix_address), "--ros", str(version)],
                                   prefix).wait_for(f"{role} ready", 60)
                ping = kids.start("ping", [PEER, "ping", str(count), "--ros", str(version)], prefix)
                result = json.loads(ping.wait_for("{", 120 + count * 0.05))
                if "error" in result or result["lost"]:
                    raise RuntimeError(f"{path} on ROS {version}: {result.get('error') or result['lost']} lost")
                out[path] = result["rtts"]
    out["floor_median"] = statistics.median(out["floor"])
    out["bridged_median"] = statistics.median(out["bridged"])
    out["added"] = out["bridged_median"] - out["floor_median"]
    return out


def main() -> int:
    """``python -m bench.ros_hop [COUNT]``: both ROS versions (those installed), a table of the medians."""
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    rows = []
    for version in (1, 2):
        if version == 1 and not shutil.which("roscore"):
            print("ROS 1 is not installed (./scripts/install-ros.sh): its row is left out", file=sys.stderr)
            continue
        if version == 2 and not ros2_env.installed():
            print(f"ROS 2 is not installed ({ros2_env.INSTALL_COMMAND}): its row is left out", file=sys.stderr)
            continue
        rows.append(measure(version, count))
    print("| ROS | floor ROS → ROS → ROS, median | via HLA ROS → HLA → ROS, median | p99 via HLA | added per hop |")
    print("|---|---|---|---|---|")
    for r in rows:
        p99 = sorted(r["bridged"])[int(0.99 * (len(r["bridged"]) - 1))]
        print(f"| ROS {r['ros']} | {r['floor_median'] * 1e3:.2f} ms | {r['bridged_median'] * 1e3:.2f} ms | "
              f"{p99 * 1e3:.2f} ms | {r['added'] * 1e3:.2f} ms |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
