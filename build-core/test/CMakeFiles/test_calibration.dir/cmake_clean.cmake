file(REMOVE_RECURSE
  "CMakeFiles/test_calibration.dir/calibration/test_calibration_step.cc.o"
  "CMakeFiles/test_calibration.dir/calibration/test_calibration_step.cc.o.d"
  "CMakeFiles/test_calibration.dir/calibration/test_coarse_mounting.cc.o"
  "CMakeFiles/test_calibration.dir/calibration/test_coarse_mounting.cc.o.d"
  "CMakeFiles/test_calibration.dir/calibration/test_dataset_diagnosis.cc.o"
  "CMakeFiles/test_calibration.dir/calibration/test_dataset_diagnosis.cc.o.d"
  "CMakeFiles/test_calibration.dir/calibration/test_fix_audit.cc.o"
  "CMakeFiles/test_calibration.dir/calibration/test_fix_audit.cc.o.d"
  "CMakeFiles/test_calibration.dir/calibration/test_odometer_delay.cc.o"
  "CMakeFiles/test_calibration.dir/calibration/test_odometer_delay.cc.o.d"
  "CMakeFiles/test_calibration.dir/calibration/test_reinitialization_prior.cc.o"
  "CMakeFiles/test_calibration.dir/calibration/test_reinitialization_prior.cc.o.d"
  "CMakeFiles/test_calibration.dir/calibration/test_rejection_share.cc.o"
  "CMakeFiles/test_calibration.dir/calibration/test_rejection_share.cc.o.d"
  "CMakeFiles/test_calibration.dir/calibration/test_weak_directions.cc.o"
  "CMakeFiles/test_calibration.dir/calibration/test_weak_directions.cc.o.d"
  "test_calibration"
  "test_calibration.pdb"
  "test_calibration[1]_tests.cmake"
  "test_calibration[2]_tests.cmake"
  "test_calibration[3]_tests.cmake"
  "test_calibration[4]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/test_calibration.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
