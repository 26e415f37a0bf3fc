set(  test_motion_TESTS)
