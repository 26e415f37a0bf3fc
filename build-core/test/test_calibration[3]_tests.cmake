add_test([=[CoarseMounting.RealHuskyLog]=]  /work/main/build-core/test/test_calibration [==[--gtest_filter=CoarseMounting.RealHuskyLog]==] --gtest_also_run_disabled_tests)
set_tests_properties([=[CoarseMounting.RealHuskyLog]=]  PROPERTIES WORKING_DIRECTORY /work/main/build-core/test SKIP_REGULAR_EXPRESSION [==[\[  SKIPPED \]]==] LABELS real_fast)
set(  test_calibration_TESTS CoarseMounting.RealHuskyLog)
