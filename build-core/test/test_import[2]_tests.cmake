set(  test_import_TESTS)
