file(REMOVE_RECURSE
  "CMakeFiles/test_io.dir/io/test_config.cc.o"
  "CMakeFiles/test_io.dir/io/test_config.cc.o.d"
  "CMakeFiles/test_io.dir/io/test_csv_logs.cc.o"
  "CMakeFiles/test_io.dir/io/test_csv_logs.cc.o.d"
  "CMakeFiles/test_io.dir/io/test_dataset_description.cc.o"
  "CMakeFiles/test_io.dir/io/test_dataset_description.cc.o.d"
  "CMakeFiles/test_io.dir/io/test_model_options.cc.o"
  "CMakeFiles/test_io.dir/io/test_model_options.cc.o.d"
  "CMakeFiles/test_io.dir/io/test_tum_trajectory.cc.o"
  "CMakeFiles/test_io.dir/io/test_tum_trajectory.cc.o.d"
  "test_io"
  "test_io.pdb"
  "test_io[1]_tests.cmake"
  "test_io[2]_tests.cmake"
  "test_io[3]_tests.cmake"
  "test_io[4]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/test_io.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
