file(REMOVE_RECURSE
  "CMakeFiles/test_motion.dir/motion/test_motion.cc.o"
  "CMakeFiles/test_motion.dir/motion/test_motion.cc.o.d"
  "test_motion"
  "test_motion.pdb"
  "test_motion[1]_tests.cmake"
  "test_motion[2]_tests.cmake"
  "test_motion[3]_tests.cmake"
  "test_motion[4]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/test_motion.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
