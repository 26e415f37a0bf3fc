set(  test_math_TESTS)
