file(REMOVE_RECURSE
  "CMakeFiles/test_import.dir/import/test_bag_gnss_comm.cc.o"
  "CMakeFiles/test_import.dir/import/test_bag_gnss_comm.cc.o.d"
  "CMakeFiles/test_import.dir/import/test_bag_import.cc.o"
  "CMakeFiles/test_import.dir/import/test_bag_import.cc.o.d"
  "CMakeFiles/test_import.dir/import/test_bag_raw_gnss.cc.o"
  "CMakeFiles/test_import.dir/import/test_bag_raw_gnss.cc.o.d"
  "CMakeFiles/test_import.dir/import/test_beidou_d2.cc.o"
  "CMakeFiles/test_import.dir/import/test_beidou_d2.cc.o.d"
  "CMakeFiles/test_import.dir/import/test_ros2_bag.cc.o"
  "CMakeFiles/test_import.dir/import/test_ros2_bag.cc.o.d"
  "CMakeFiles/test_import.dir/import/test_ros_message.cc.o"
  "CMakeFiles/test_import.dir/import/test_ros_message.cc.o.d"
  "CMakeFiles/test_import.dir/import/test_ubx_parts.cc.o"
  "CMakeFiles/test_import.dir/import/test_ubx_parts.cc.o.d"
  "CMakeFiles/test_import.dir/import/test_ubx_real.cc.o"
  "CMakeFiles/test_import.dir/import/test_ubx_real.cc.o.d"
  "test_import"
  "test_import.pdb"
  "test_import[1]_tests.cmake"
  "test_import[2]_tests.cmake"
  "test_import[3]_tests.cmake"
  "test_import[4]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/test_import.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
