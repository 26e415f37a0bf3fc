
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/test/gnss/test_code_outlier_check.cc" "test/CMakeFiles/test_gnss.dir/gnss/test_code_outlier_check.cc.o" "gcc" "test/CMakeFiles/test_gnss.dir/gnss/test_code_outlier_check.cc.o.d"
  "/work/main/test/gnss/test_cycle_slip.cc" "test/CMakeFiles/test_gnss.dir/gnss/test_cycle_slip.cc.o" "gcc" "test/CMakeFiles/test_gnss.dir/gnss/test_cycle_slip.cc.o.d"
  "/work/main/test/gnss/test_ephemeris.cc" "test/CMakeFiles/test_gnss.dir/gnss/test_ephemeris.cc.o" "gcc" "test/CMakeFiles/test_gnss.dir/gnss/test_ephemeris.cc.o.d"
  "/work/main/test/gnss/test_fixed_phase_covariance.cc" "test/CMakeFiles/test_gnss.dir/gnss/test_fixed_phase_covariance.cc.o" "gcc" "test/CMakeFiles/test_gnss.dir/gnss/test_fixed_phase_covariance.cc.o.d"
  "/work/main/test/gnss/test_lambda.cc" "test/CMakeFiles/test_gnss.dir/gnss/test_lambda.cc.o" "gcc" "test/CMakeFiles/test_gnss.dir/gnss/test_lambda.cc.o.d"
  "/work/main/test/gnss/test_rinex.cc" "test/CMakeFiles/test_gnss.dir/gnss/test_rinex.cc.o" "gcc" "test/CMakeFiles/test_gnss.dir/gnss/test_rinex.cc.o.d"
  "/work/main/test/gnss/test_rtk.cc" "test/CMakeFiles/test_gnss.dir/gnss/test_rtk.cc.o" "gcc" "test/CMakeFiles/test_gnss.dir/gnss/test_rtk.cc.o.d"
  "/work/main/test/gnss/test_spp.cc" "test/CMakeFiles/test_gnss.dir/gnss/test_spp.cc.o" "gcc" "test/CMakeFiles/test_gnss.dir/gnss/test_spp.cc.o.d"
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
