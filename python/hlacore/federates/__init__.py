"""Reusable federates: the library's middle layer, above the core (:mod:`hlacore.rti`, ...) and below the
papers' experiments (:mod:`hlacore.experiments`), which nothing here imports.

Lowest first (a package imports only lower ones; tests/system/test_layers.py checks it):

- :mod:`.de` — the discrete-event engine and its HLA-aware director (``docs/de.md``);
- :mod:`.robot_world` — the pymunk world of Stage-style robots and its federate (``docs/robot-world.md``);
- :mod:`.robot_driver` — the Robot Federate and its device (``docs/robot.md``);
- :mod:`.ros_bridge` — the ROS bridge (ROS 1 and ROS 2) and the stageros-style world node (``docs/ros-bridge.md``);
- :mod:`.testbench` — the UVM-style testbench on the DE engine (``docs/robot.md``).

``mirror`` and the ``paper1*`` modules here are deprecated aliases of their new homes under
:mod:`hlacore.experiments`, kept for one release.
"""
