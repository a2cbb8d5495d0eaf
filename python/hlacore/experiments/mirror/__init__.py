"""Paper 2 §6.2 (testing-rtes-hla-2016): a "real" robot mirrored by a world robot whose virtual sonar it
reads, a third robot driven by a plain ROS node, the reference trajectory, and their comparison
(docs/mirror.md).

- :mod:`.scenario` — the world: two lanes, a box on each;
- :mod:`.reference` — the ideal controller on an ideal body (computed);
- :mod:`.node` — the ROS robot's controller, a plain rospy node;
- :mod:`.run` — one run: world federate + bridge here, robot federate + device and the node as processes;
- :mod:`.metrics` — Hausdorff distance between paths, box clearance;
- :mod:`.outputs` — CSV trace and trajectory plot;
(the run's ROS master, started when none answers, comes from :mod:`hlacore.federates.ros_bridge.master`).

``python -m hlacore.experiments.mirror --help`` runs it.

Experiments layer: built on :mod:`hlacore.federates.robot_world`, :mod:`~hlacore.federates.robot_driver`
(the §6.2 robot, :mod:`~hlacore.federates.robot_driver.mirrored`) and :mod:`~hlacore.federates.ros_bridge`.
"""
