"""Ready-made federates (discrete-event engine, robot world, ROS bridge, robot driver, test bench).

None has landed yet: they are tracked by their own issues.
"""
