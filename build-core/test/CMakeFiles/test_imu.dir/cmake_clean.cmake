file(REMOVE_RECURSE
  "CMakeFiles/test_imu.dir/imu/test_imu_preintegration.cc.o"
  "CMakeFiles/test_imu.dir/imu/test_imu_preintegration.cc.o.d"
  "CMakeFiles/test_imu.dir/imu/test_static_alignment.cc.o"
  "CMakeFiles/test_imu.dir/imu/test_static_alignment.cc.o.d"
  "test_imu"
  "test_imu.pdb"
  "test_imu[1]_tests.cmake"
  "test_imu[2]_tests.cmake"
  "test_imu[3]_tests.cmake"
  "test_imu[4]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/test_imu.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
