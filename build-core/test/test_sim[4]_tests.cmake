set(  test_sim_TESTS)
