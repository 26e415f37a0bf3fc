file(REMOVE_RECURSE
  "CMakeFiles/giocal.dir/calibrate_command.cc.o"
  "CMakeFiles/giocal.dir/calibrate_command.cc.o.d"
  "CMakeFiles/giocal.dir/check_command.cc.o"
  "CMakeFiles/giocal.dir/check_command.cc.o.d"
  "CMakeFiles/giocal.dir/command_line.cc.o"
  "CMakeFiles/giocal.dir/command_line.cc.o.d"
  "CMakeFiles/giocal.dir/compare_command.cc.o"
  "CMakeFiles/giocal.dir/compare_command.cc.o.d"
  "CMakeFiles/giocal.dir/dataset_commands.cc.o"
  "CMakeFiles/giocal.dir/dataset_commands.cc.o.d"
  "CMakeFiles/giocal.dir/deadreckon_command.cc.o"
  "CMakeFiles/giocal.dir/deadreckon_command.cc.o.d"
  "CMakeFiles/giocal.dir/giocal_main.cc.o"
  "CMakeFiles/giocal.dir/giocal_main.cc.o.d"
  "CMakeFiles/giocal.dir/import_command.cc.o"
  "CMakeFiles/giocal.dir/import_command.cc.o.d"
  "CMakeFiles/giocal.dir/import_i2nav.cc.o"
  "CMakeFiles/giocal.dir/import_i2nav.cc.o.d"
  "CMakeFiles/giocal.dir/interrupt_watch.cc.o"
  "CMakeFiles/giocal.dir/interrupt_watch.cc.o.d"
  "CMakeFiles/giocal.dir/observability_command.cc.o"
  "CMakeFiles/giocal.dir/observability_command.cc.o.d"
  "CMakeFiles/giocal.dir/report_command.cc.o"
  "CMakeFiles/giocal.dir/report_command.cc.o.d"
  "CMakeFiles/giocal.dir/simulate_command.cc.o"
  "CMakeFiles/giocal.dir/simulate_command.cc.o.d"
  "CMakeFiles/giocal.dir/validate_command.cc.o"
  "CMakeFiles/giocal.dir/validate_command.cc.o.d"
  "giocal"
  "giocal.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/giocal.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
