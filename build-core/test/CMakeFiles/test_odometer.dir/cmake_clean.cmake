file(REMOVE_RECURSE
  "CMakeFiles/test_odometer.dir/odometer/test_odometer.cc.o"
  "CMakeFiles/test_odometer.dir/odometer/test_odometer.cc.o.d"
  "test_odometer"
  "test_odometer.pdb"
  "test_odometer[1]_tests.cmake"
  "test_odometer[2]_tests.cmake"
  "test_odometer[3]_tests.cmake"
  "test_odometer[4]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/test_odometer.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
