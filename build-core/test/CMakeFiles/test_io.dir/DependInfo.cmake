
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/test/io/test_config.cc" "test/CMakeFiles/test_io.dir/io/test_config.cc.o" "gcc" "test/CMakeFiles/test_io.dir/io/test_config.cc.o.d"
  "/work/main/test/io/test_csv_logs.cc" "test/CMakeFiles/test_io.dir/io/test_csv_logs.cc.o" "gcc" "test/CMakeFiles/test_io.dir/io/test_csv_logs.cc.o.d"
  "/work/main/test/io/test_dataset_description.cc" "test/CMakeFiles/test_io.dir/io/test_dataset_description.cc.o" "gcc" "test/CMakeFiles/test_io.dir/io/test_dataset_description.cc.o.d"
  "/work/main/test/io/test_model_options.cc" "test/CMakeFiles/test_io.dir/io/test_model_options.cc.o" "gcc" "test/CMakeFiles/test_io.dir/io/test_model_options.cc.o.d"
  "/work/main/test/io/test_tum_trajectory.cc" "test/CMakeFiles/test_io.dir/io/test_tum_trajectory.cc.o" "gcc" "test/CMakeFiles/test_io.dir/io/test_tum_trajectory.cc.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build-core/common/CMakeFiles/giocal_common.dir/DependInfo.cmake"
  "/work/main/build-core/sim/CMakeFiles/giocal_sim.dir/DependInfo.cmake"
  "/work/main/build-core/replay/CMakeFiles/giocal_replay.dir/DependInfo.cmake"
  "/work/main/build-core/evaluation/CMakeFiles/giocal_evaluation.dir/DependInfo.cmake"
  "/work/main/build-core/options/CMakeFiles/giocal_options.dir/DependInfo.cmake"
  "/work/main/build-core/ekf/CMakeFiles/giocal_ekf.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
