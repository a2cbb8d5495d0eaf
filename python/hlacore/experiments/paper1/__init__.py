"""Paper 1 (ros-ptolemy-hla-iess2015): an avatar with a sonar drives toward a wall while three obstacle
robots cross its way, in four set-ups of growing scope (docs/robot-world.md, docs/ros-bridge.md).

- :mod:`.scenario` — the world, the go / slow / stop controller and the obstacles' driver, run on the
  robot world alone (``python -m hlacore.experiments.paper1.scenario [OUTDIR]``);
- :mod:`.hla` — the same through the RTI: world federate + a controller federate in lockstep;
- :mod:`.de_controller` — the controller as a DE-engine federate (Ptolemy's role, Fig. 6);
- :mod:`.checks` — the checks on a run through the RTI;
- :mod:`.ros` — through ROS: world federate + ROS bridge + the controllers as a rospy node
  (``python -m hlacore.experiments.paper1.ros OUTDIR [--controller de]``);
- :mod:`.chain` — paper 1's own architecture: DE federate -> RTI -> bridge -> ROS -> stage node.

Experiments layer: imports the core and the federates, never the reverse.
"""
