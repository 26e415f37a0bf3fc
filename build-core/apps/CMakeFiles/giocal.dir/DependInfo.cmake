
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/apps/calibrate_command.cc" "apps/CMakeFiles/giocal.dir/calibrate_command.cc.o" "gcc" "apps/CMakeFiles/giocal.dir/calibrate_command.cc.o.d"
  "/work/main/apps/check_command.cc" "apps/CMakeFiles/giocal.dir/check_command.cc.o" "gcc" "apps/CMakeFiles/giocal.dir/check_command.cc.o.d"
  "/work/main/apps/command_line.cc" "apps/CMakeFiles/giocal.dir/command_line.cc.o" "gcc" "apps/CMakeFiles/giocal.dir/command_line.cc.o.d"
  "/work/main/apps/compare_command.cc" "apps/CMakeFiles/giocal.dir/compare_command.cc.o" "gcc" "apps/CMakeFiles/giocal.dir/compare_command.cc.o.d"
  "/work/main/apps/dataset_commands.cc" "apps/CMakeFiles/giocal.dir/dataset_commands.cc.o" "gcc" "apps/CMakeFiles/giocal.dir/dataset_commands.cc.o.d"
  "/work/main/apps/deadreckon_command.cc" "apps/CMakeFiles/giocal.dir/deadreckon_command.cc.o" "gcc" "apps/CMakeFiles/giocal.dir/deadreckon_command.cc.o.d"
  "/work/main/apps/giocal_main.cc" "apps/CMakeFiles/giocal.dir/giocal_main.cc.o" "gcc" "apps/CMakeFiles/giocal.dir/giocal_main.cc.o.d"
  "/work/main/apps/import_command.cc" "apps/CMakeFiles/giocal.dir/import_command.cc.o" "gcc" "apps/CMakeFiles/giocal.dir/import_command.cc.o.d"
  "/work/main/apps/import_i2nav.cc" "apps/CMakeFiles/giocal.dir/import_i2nav.cc.o" "gcc" "apps/CMakeFiles/giocal.dir/import_i2nav.cc.o.d"
  "/work/main/apps/interrupt_watch.cc" "apps/CMakeFiles/giocal.dir/interrupt_watch.cc.o" "gcc" "apps/CMakeFiles/giocal.dir/interrupt_watch.cc.o.d"
  "/work/main/apps/observability_command.cc" "apps/CMakeFiles/giocal.dir/observability_command.cc.o" "gcc" "apps/CMakeFiles/giocal.dir/observability_command.cc.o.d"
  "/work/main/apps/report_command.cc" "apps/CMakeFiles/giocal.dir/report_command.cc.o" "gcc" "apps/CMakeFiles/giocal.dir/report_command.cc.o.d"
  "/work/main/apps/simulate_command.cc" "apps/CMakeFiles/giocal.dir/simulate_command.cc.o" "gcc" "apps/CMakeFiles/giocal.dir/simulate_command.cc.o.d"
  "/work/main/apps/validate_command.cc" "apps/CMakeFiles/giocal.dir/validate_command.cc.o" "gcc" "apps/CMakeFiles/giocal.dir/validate_command.cc.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build-core/common/CMakeFiles/giocal_common.dir/DependInfo.cmake"
  "/work/main/build-core/sim/CMakeFiles/giocal_sim.dir/DependInfo.cmake"
  "/work/main/build-core/replay/CMakeFiles/giocal_replay.dir/DependInfo.cmake"
  "/work/main/build-core/evaluation/CMakeFiles/giocal_evaluation.dir/DependInfo.cmake"
  "/work/main/build-core/options/CMakeFiles/giocal_options.dir/DependInfo.cmake"
  "/work/main/build-core/import/CMakeFiles/giocal_import.dir/DependInfo.cmake"
  "/work/main/build-core/ekf/CMakeFiles/giocal_ekf.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
