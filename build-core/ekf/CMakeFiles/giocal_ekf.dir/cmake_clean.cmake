file(REMOVE_RECURSE
  "CMakeFiles/giocal_ekf.dir/calibration_filter.cc.o"
  "CMakeFiles/giocal_ekf.dir/calibration_filter.cc.o.d"
  "CMakeFiles/giocal_ekf.dir/ekf_core.cc.o"
  "CMakeFiles/giocal_ekf.dir/ekf_core.cc.o.d"
  "CMakeFiles/giocal_ekf.dir/filter_readout.cc.o"
  "CMakeFiles/giocal_ekf.dir/filter_readout.cc.o.d"
  "CMakeFiles/giocal_ekf.dir/gnss_update.cc.o"
  "CMakeFiles/giocal_ekf.dir/gnss_update.cc.o.d"
  "CMakeFiles/giocal_ekf.dir/imu_propagation.cc.o"
  "CMakeFiles/giocal_ekf.dir/imu_propagation.cc.o.d"
  "CMakeFiles/giocal_ekf.dir/state_registry.cc.o"
  "CMakeFiles/giocal_ekf.dir/state_registry.cc.o.d"
  "libgiocal_ekf.a"
  "libgiocal_ekf.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/giocal_ekf.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
