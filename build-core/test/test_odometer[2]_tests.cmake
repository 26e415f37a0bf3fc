set(  test_odometer_TESTS)
