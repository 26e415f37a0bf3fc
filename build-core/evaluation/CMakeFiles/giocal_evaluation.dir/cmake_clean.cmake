file(REMOVE_RECURSE
  "CMakeFiles/giocal_evaluation.dir/calibration_source.cc.o"
  "CMakeFiles/giocal_evaluation.dir/calibration_source.cc.o.d"
  "CMakeFiles/giocal_evaluation.dir/dead_reckoning.cc.o"
  "CMakeFiles/giocal_evaluation.dir/dead_reckoning.cc.o.d"
  "CMakeFiles/giocal_evaluation.dir/ideal_imu.cc.o"
  "CMakeFiles/giocal_evaluation.dir/ideal_imu.cc.o.d"
  "CMakeFiles/giocal_evaluation.dir/observability.cc.o"
  "CMakeFiles/giocal_evaluation.dir/observability.cc.o.d"
  "CMakeFiles/giocal_evaluation.dir/validation.cc.o"
  "CMakeFiles/giocal_evaluation.dir/validation.cc.o.d"
  "libgiocal_evaluation.a"
  "libgiocal_evaluation.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/giocal_evaluation.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
