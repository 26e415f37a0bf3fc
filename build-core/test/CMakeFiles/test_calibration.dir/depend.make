# Empty dependencies file for test_calibration.
# This may be replaced when dependencies are built.
