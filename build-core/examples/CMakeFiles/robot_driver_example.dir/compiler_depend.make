# Empty compiler generated dependencies file for robot_driver_example.
# This may be replaced when dependencies are built.
