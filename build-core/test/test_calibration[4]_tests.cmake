set(  test_calibration_TESTS)
