set(  test_ekf_TESTS)
