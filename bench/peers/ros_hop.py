"""The processes of the ROS bridge hop bench (bench/ros_hop.py), one role each, on ROS 1 or ROS 2 (--ros):

    ros_hop.py ping COUNT --ros N   publishes Twist #k (linear.x = k) on /ping/cmd_vel every 5 ms once something
                                    listens there, times until #k comes back on /pong/cmd_vel; prints one JSON
                                    line of the round trips (seconds), the first COUNT // 10 left out (warm-up)
    ros_hop.py relay --ros N        the floor: republishes each Twist of /ping/cmd_vel on /pong/cmd_vel
    ros_hop.py into-hla RTIG --ros N    a bridge: /ping/cmd_vel → cmd_vel interactions for robot "ping"
    ros_hop.py out-of-hla RTIG --ros N  a bridge: cmd_vel interactions for "ping" → Twists on /pong/cmd_vel

Both bridges untimed (receive order): the hop's latency, not time management's. Each prints "ROLE ready"
once its node is up, and stops on SIGTERM."""

from __future__ import annotations

import json
import signal
import sys
import threading
import time
from typing import Any

from hlacore.federates.ros_bridge import RosBridge, TwistIn, TwistOut, select


def main() -> int:
    role, ros_version = sys.argv[1], int(sys.argv[sys.argv.index("--ros") + 1])
    stop = threading.Event()
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    if role in ("into-hla", "out-of-hla"):
        mappings = [TwistIn("/ping/cmd_vel", "ping")] if role == "into-hla" else [TwistOut("ping", "/pong/cmd_vel")]
        bridge = RosBridge(mappings, sys.argv[2], federate_name=f"hop-{role}", node_name=f"hop_{role.replace('-', '_')}",
                           timed=False, ros=select(ros_version))
        signal.signal(signal.SIGTERM, lambda *_: bridge.stop())
        bridge.start()
        print(f"{role} ready", flush=True)
        try:
            bridge.spin(cycle_timeout=0.001)
        finally:
            bridge.close()
        return 0
    ros = select(ros_version)
    ros.init_node(f"hop_{role}")
    Twist = ros.msgs.Twist
    if role == "relay":
        out = ros.publisher("/pong/cmd_vel", Twist, synchronous=True)
        sub = ros.subscriber("/ping/cmd_vel", Twist, out.publish)
        print("relay ready", flush=True)
        stop.wait()
        ros.unsubscribe(sub)
        ros.shutdown("stopped")
        return 0
    count = int(sys.argv[2])
    back: dict[int, int] = {}
    arrived = threading.Condition()

    def on_pong(msg: Any) -> None:
        with arrived:
            back[int(msg.linear.x)] = time.perf_counter_ns()
            arrived.notify_all()

    sub = ros.subscriber("/pong/cmd_vel", Twist, on_pong)
    pub = ros.publisher("/ping/cmd_vel", Twist, synchronous=True)
    print("ping ready", flush=True)
    deadline = time.monotonic() + 60
    while (ros.publisher_connections(pub) == 0 or ros.subscriber_connections(sub) == 0) and not stop.is_set():
        if time.monotonic() > deadline:
            print(json.dumps({"error": "no connection"}), flush=True)
            return 2
        time.sleep(0.01)
    time.sleep(0.5)  # the path behind the first hop (the other bridge, the gateway) settles
    rtts, lost = [], 0
    for k in range(count):
        msg = Twist()
        msg.linear.x = float(k)
        sent = time.perf_counter_ns()
        pub.publish(msg)
        with arrived:
            if not arrived.wait_for(lambda: k in back, 2.0):
                lost += 1
                continue
        if k >= count // 10:
            rtts.append((back[k] - sent) * 1e-9)
        time.sleep(0.005)
    print(json.dumps({"rtts": rtts, "lost": lost}), flush=True)
    ros.unsubscribe(sub)
    ros.shutdown("done")
    return 0


if __name__ == "__main__":
    sys.exit(main())
