file(REMOVE_RECURSE
  "CMakeFiles/robot_driver_example.dir/robot_driver.cc.o"
  "CMakeFiles/robot_driver_example.dir/robot_driver.cc.o.d"
  "robot_driver_example"
  "robot_driver_example.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/robot_driver_example.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
