file(REMOVE_RECURSE
  "CMakeFiles/test_sim.dir/sim/test_gnss_simulation.cc.o"
  "CMakeFiles/test_sim.dir/sim/test_gnss_simulation.cc.o.d"
  "CMakeFiles/test_sim.dir/sim/test_scenes.cc.o"
  "CMakeFiles/test_sim.dir/sim/test_scenes.cc.o.d"
  "CMakeFiles/test_sim.dir/sim/test_simulator.cc.o"
  "CMakeFiles/test_sim.dir/sim/test_simulator.cc.o.d"
  "test_sim"
  "test_sim.pdb"
  "test_sim[1]_tests.cmake"
  "test_sim[2]_tests.cmake"
  "test_sim[3]_tests.cmake"
  "test_sim[4]_tests.cmake"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/test_sim.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
