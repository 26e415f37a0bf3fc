set(  test_geodesy_TESTS)
