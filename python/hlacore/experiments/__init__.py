"""The papers' experiments: scenarios and runners built on the library, not part of it.

- :mod:`.robot_in_the_loop` — testing-rtes-hla-2016 §6: the robot-in-the-loop A* experiment, the
  README's main job (``python -m hlacore.experiments.robot_in_the_loop``, ``./scripts/run.sh``);
- :mod:`.mirror` — testing-rtes-hla-2016 §6.2: a real robot, its mirror in the world, a ROS robot;
- :mod:`.paper1` — ros-ptolemy-hla-iess2015: avatar, crossing obstacles and a wall, from the world alone to
  paper 1's own chain through ROS.

Top layer: experiments import the core (:mod:`hlacore.rti`, ...) and the federates
(:mod:`hlacore.federates`); nothing below imports them (tests/system/test_layers.py checks it). Their old paths
under ``hlacore.federates`` and ``hlacore.demo`` are deprecated aliases for one release.
"""
