file(REMOVE_RECURSE
  "CMakeFiles/test_math.dir/math/test_null_space.cc.o"
  "CMakeFiles/test_math.dir/math/test_null_space.cc.o.d"
  "CMakeFiles/test_math.dir/math/test_row_compression.cc.o"
  "CMakeFiles/test_math.dir/math/test_row_compression.cc.o.d"
  "CMakeFiles/test_math.dir/math/test_so3.cc.o"
  "CMakeFiles/test_math.dir/math/test_so3.cc.o.d"
  "test_math"
  "test_math.pdb"
  "test_math[1]_tests.cmake"
  "test_math[2]_tests.cmake"
  "test_math[3]_tests.cmake"
  "test_math[4]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/test_math.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
