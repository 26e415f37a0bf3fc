set(  test_gnss_TESTS)
