# Empty compiler generated dependencies file for test_imu.
# This may be replaced when dependencies are built.
