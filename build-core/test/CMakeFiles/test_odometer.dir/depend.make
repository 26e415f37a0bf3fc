# Empty dependencies file for test_odometer.
# This may be replaced when dependencies are built.
