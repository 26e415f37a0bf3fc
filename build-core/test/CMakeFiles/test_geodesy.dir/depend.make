# Empty dependencies file for test_geodesy.
# This may be replaced when dependencies are built.
