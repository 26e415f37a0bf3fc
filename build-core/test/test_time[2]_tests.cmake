set(  test_time_TESTS)
