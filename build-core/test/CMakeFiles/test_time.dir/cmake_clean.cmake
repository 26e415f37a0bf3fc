file(REMOVE_RECURSE
  "CMakeFiles/test_time.dir/time/test_gps_time.cc.o"
  "CMakeFiles/test_time.dir/time/test_gps_time.cc.o.d"
  "test_time"
  "test_time.pdb"
  "test_time[1]_tests.cmake"
  "test_time[2]_tests.cmake"
  "test_time[3]_tests.cmake"
  "test_time[4]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/test_time.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
