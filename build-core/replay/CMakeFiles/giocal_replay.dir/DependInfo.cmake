
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/replay/estimator_factory.cc" "replay/CMakeFiles/giocal_replay.dir/estimator_factory.cc.o" "gcc" "replay/CMakeFiles/giocal_replay.dir/estimator_factory.cc.o.d"
  "/work/main/replay/measured_delay.cc" "replay/CMakeFiles/giocal_replay.dir/measured_delay.cc.o" "gcc" "replay/CMakeFiles/giocal_replay.dir/measured_delay.cc.o.d"
  "/work/main/replay/replay.cc" "replay/CMakeFiles/giocal_replay.dir/replay.cc.o" "gcc" "replay/CMakeFiles/giocal_replay.dir/replay.cc.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build-core/common/CMakeFiles/giocal_common.dir/DependInfo.cmake"
  "/work/main/build-core/ekf/CMakeFiles/giocal_ekf.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
