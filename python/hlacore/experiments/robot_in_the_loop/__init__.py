"""The robot-in-the-loop A* experiment of testing-rtes-hla-2016 §6 (docs/robot.md), the README's main job.

- :mod:`.experiment` — :func:`~.experiment.run_experiment`: the testbench federate here, the Robot Federate
  in its own process (``python -m hlacore.federates.robot_driver``), the outputs;
- ``__main__`` — the command line (``python -m hlacore.experiments.robot_in_the_loop``, ``./scripts/run.sh``).

Experiments layer: built on :mod:`hlacore.federates.testbench` and :mod:`hlacore.federates.robot_driver`.
"""
