
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/ekf/calibration_filter.cc" "ekf/CMakeFiles/giocal_ekf.dir/calibration_filter.cc.o" "gcc" "ekf/CMakeFiles/giocal_ekf.dir/calibration_filter.cc.o.d"
  "/work/main/ekf/ekf_core.cc" "ekf/CMakeFiles/giocal_ekf.dir/ekf_core.cc.o" "gcc" "ekf/CMakeFiles/giocal_ekf.dir/ekf_core.cc.o.d"
  "/work/main/ekf/filter_readout.cc" "ekf/CMakeFiles/giocal_ekf.dir/filter_readout.cc.o" "gcc" "ekf/CMakeFiles/giocal_ekf.dir/filter_readout.cc.o.d"
  "/work/main/ekf/gnss_update.cc" "ekf/CMakeFiles/giocal_ekf.dir/gnss_update.cc.o" "gcc" "ekf/CMakeFiles/giocal_ekf.dir/gnss_update.cc.o.d"
  "/work/main/ekf/imu_propagation.cc" "ekf/CMakeFiles/giocal_ekf.dir/imu_propagation.cc.o" "gcc" "ekf/CMakeFiles/giocal_ekf.dir/imu_propagation.cc.o.d"
  "/work/main/ekf/state_registry.cc" "ekf/CMakeFiles/giocal_ekf.dir/state_registry.cc.o" "gcc" "ekf/CMakeFiles/giocal_ekf.dir/state_registry.cc.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build-core/common/CMakeFiles/giocal_common.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
