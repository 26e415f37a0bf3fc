set(  test_imu_TESTS)
