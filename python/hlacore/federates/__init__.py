"""Ready-made federates (discrete-event engine, robot world, ROS bridge, robot driver, test bench).

- :mod:`hlacore.federates.de` — the discrete-event engine and its HLA-aware director (``docs/de.md``).

The others are tracked by their own issues.
"""
