file(REMOVE_RECURSE
  "CMakeFiles/test_gnss.dir/gnss/test_code_outlier_check.cc.o"
  "CMakeFiles/test_gnss.dir/gnss/test_code_outlier_check.cc.o.d"
  "CMakeFiles/test_gnss.dir/gnss/test_cycle_slip.cc.o"
  "CMakeFiles/test_gnss.dir/gnss/test_cycle_slip.cc.o.d"
  "CMakeFiles/test_gnss.dir/gnss/test_ephemeris.cc.o"
  "CMakeFiles/test_gnss.dir/gnss/test_ephemeris.cc.o.d"
  "CMakeFiles/test_gnss.dir/gnss/test_fixed_phase_covariance.cc.o"
  "CMakeFiles/test_gnss.dir/gnss/test_fixed_phase_covariance.cc.o.d"
  "CMakeFiles/test_gnss.dir/gnss/test_lambda.cc.o"
  "CMakeFiles/test_gnss.dir/gnss/test_lambda.cc.o.d"
  "CMakeFiles/test_gnss.dir/gnss/test_rinex.cc.o"
  "CMakeFiles/test_gnss.dir/gnss/test_rinex.cc.o.d"
  "CMakeFiles/test_gnss.dir/gnss/test_rtk.cc.o"
  "CMakeFiles/test_gnss.dir/gnss/test_rtk.cc.o.d"
  "CMakeFiles/test_gnss.dir/gnss/test_spp.cc.o"
  "CMakeFiles/test_gnss.dir/gnss/test_spp.cc.o.d"
  "test_gnss"
  "test_gnss.pdb"
  "test_gnss[1]_tests.cmake"
  "test_gnss[2]_tests.cmake"
  "test_gnss[3]_tests.cmake"
  "test_gnss[4]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/test_gnss.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
