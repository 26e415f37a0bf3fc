file(REMOVE_RECURSE
  "CMakeFiles/giocal_replay.dir/estimator_factory.cc.o"
  "CMakeFiles/giocal_replay.dir/estimator_factory.cc.o.d"
  "CMakeFiles/giocal_replay.dir/measured_delay.cc.o"
  "CMakeFiles/giocal_replay.dir/measured_delay.cc.o.d"
  "CMakeFiles/giocal_replay.dir/replay.cc.o"
  "CMakeFiles/giocal_replay.dir/replay.cc.o.d"
  "libgiocal_replay.a"
  "libgiocal_replay.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/giocal_replay.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
