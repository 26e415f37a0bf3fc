add_test([=[SimConfig.ManyLapsReadFast]=]  /work/main/build-core/test/test_sim [==[--gtest_filter=SimConfig.ManyLapsReadFast]==] --gtest_also_run_disabled_tests)
set_tests_properties([=[SimConfig.ManyLapsReadFast]=]  PROPERTIES WORKING_DIRECTORY /work/main/build-core/test SKIP_REGULAR_EXPRESSION [==[\[  SKIPPED \]]==] LABELS real_fast)
set(  test_sim_TESTS SimConfig.ManyLapsReadFast)
