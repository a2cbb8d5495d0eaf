"""An FMU in the loop of the robot world: a waypoint controller exported as an FMI 2 co-simulation FMU (our
own model, in C: ``controller/``) drives a robot of the pymunk world through the federation, without a line
of glue code; ``python -m hlacore.experiments.fmu_drive`` (docs/fmu.md, "An FMU in the loop")."""
