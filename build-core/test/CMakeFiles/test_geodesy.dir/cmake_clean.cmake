file(REMOVE_RECURSE
  "CMakeFiles/test_geodesy.dir/geodesy/test_wgs84.cc.o"
  "CMakeFiles/test_geodesy.dir/geodesy/test_wgs84.cc.o.d"
  "test_geodesy"
  "test_geodesy.pdb"
  "test_geodesy[1]_tests.cmake"
  "test_geodesy[2]_tests.cmake"
  "test_geodesy[3]_tests.cmake"
  "test_geodesy[4]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/test_geodesy.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
