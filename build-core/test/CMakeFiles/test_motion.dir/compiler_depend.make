# Empty compiler generated dependencies file for test_motion.
# This may be replaced when dependencies are built.
