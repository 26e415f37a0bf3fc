# Empty dependencies file for test_ekf.
# This may be replaced when dependencies are built.
