# Empty compiler generated dependencies file for test_gnss.
# This may be replaced when dependencies are built.
