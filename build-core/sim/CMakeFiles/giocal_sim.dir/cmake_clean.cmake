file(REMOVE_RECURSE
  "CMakeFiles/giocal_sim.dir/gnss_simulator.cc.o"
  "CMakeFiles/giocal_sim.dir/gnss_simulator.cc.o.d"
  "CMakeFiles/giocal_sim.dir/motion_profile.cc.o"
  "CMakeFiles/giocal_sim.dir/motion_profile.cc.o.d"
  "CMakeFiles/giocal_sim.dir/sensor_errors.cc.o"
  "CMakeFiles/giocal_sim.dir/sensor_errors.cc.o.d"
  "CMakeFiles/giocal_sim.dir/sim_config.cc.o"
  "CMakeFiles/giocal_sim.dir/sim_config.cc.o.d"
  "CMakeFiles/giocal_sim.dir/simulator.cc.o"
  "CMakeFiles/giocal_sim.dir/simulator.cc.o.d"
  "CMakeFiles/giocal_sim.dir/trajectory.cc.o"
  "CMakeFiles/giocal_sim.dir/trajectory.cc.o.d"
  "libgiocal_sim.a"
  "libgiocal_sim.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/giocal_sim.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
