file(REMOVE_RECURSE
  "CMakeFiles/test_ekf.dir/ekf/test_calibrator.cc.o"
  "CMakeFiles/test_ekf.dir/ekf/test_calibrator.cc.o.d"
  "CMakeFiles/test_ekf.dir/ekf/test_imu_propagation.cc.o"
  "CMakeFiles/test_ekf.dir/ekf/test_imu_propagation.cc.o.d"
  "CMakeFiles/test_ekf.dir/ekf/test_state_registry.cc.o"
  "CMakeFiles/test_ekf.dir/ekf/test_state_registry.cc.o.d"
  "test_ekf"
  "test_ekf.pdb"
  "test_ekf[1]_tests.cmake"
  "test_ekf[2]_tests.cmake"
  "test_ekf[3]_tests.cmake"
  "test_ekf[4]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/test_ekf.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
