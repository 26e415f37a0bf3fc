
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/sim/gnss_simulator.cc" "sim/CMakeFiles/giocal_sim.dir/gnss_simulator.cc.o" "gcc" "sim/CMakeFiles/giocal_sim.dir/gnss_simulator.cc.o.d"
  "/work/main/sim/motion_profile.cc" "sim/CMakeFiles/giocal_sim.dir/motion_profile.cc.o" "gcc" "sim/CMakeFiles/giocal_sim.dir/motion_profile.cc.o.d"
  "/work/main/sim/sensor_errors.cc" "sim/CMakeFiles/giocal_sim.dir/sensor_errors.cc.o" "gcc" "sim/CMakeFiles/giocal_sim.dir/sensor_errors.cc.o.d"
  "/work/main/sim/sim_config.cc" "sim/CMakeFiles/giocal_sim.dir/sim_config.cc.o" "gcc" "sim/CMakeFiles/giocal_sim.dir/sim_config.cc.o.d"
  "/work/main/sim/simulator.cc" "sim/CMakeFiles/giocal_sim.dir/simulator.cc.o" "gcc" "sim/CMakeFiles/giocal_sim.dir/simulator.cc.o.d"
  "/work/main/sim/trajectory.cc" "sim/CMakeFiles/giocal_sim.dir/trajectory.cc.o" "gcc" "sim/CMakeFiles/giocal_sim.dir/trajectory.cc.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build-core/common/CMakeFiles/giocal_common.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
