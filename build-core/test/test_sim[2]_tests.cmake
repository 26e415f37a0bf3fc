add_test([=[GnssSimulation.GiocalRtkFixesUnderTreesAreWithin5cm]=]  /work/main/build-core/test/test_sim [==[--gtest_filter=GnssSimulation.GiocalRtkFixesUnderTreesAreWithin5cm]==] --gtest_also_run_disabled_tests)
set_tests_properties([=[GnssSimulation.GiocalRtkFixesUnderTreesAreWithin5cm]=]  PROPERTIES WORKING_DIRECTORY /work/main/build-core/test SKIP_REGULAR_EXPRESSION [==[\[  SKIPPED \]]==] LABELS slow)
set(  test_sim_TESTS GnssSimulation.GiocalRtkFixesUnderTreesAreWithin5cm)
