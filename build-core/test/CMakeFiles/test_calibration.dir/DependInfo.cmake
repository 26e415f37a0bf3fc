
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/test/calibration/test_calibration_step.cc" "test/CMakeFiles/test_calibration.dir/calibration/test_calibration_step.cc.o" "gcc" "test/CMakeFiles/test_calibration.dir/calibration/test_calibration_step.cc.o.d"
  "/work/main/test/calibration/test_coarse_mounting.cc" "test/CMakeFiles/test_calibration.dir/calibration/test_coarse_mounting.cc.o" "gcc" "test/CMakeFiles/test_calibration.dir/calibration/test_coarse_mounting.cc.o.d"
  "/work/main/test/calibration/test_dataset_diagnosis.cc" "test/CMakeFiles/test_calibration.dir/calibration/test_dataset_diagnosis.cc.o" "gcc" "test/CMakeFiles/test_calibration.dir/calibration/test_dataset_diagnosis.cc.o.d"
  "/work/main/test/calibration/test_fix_audit.cc" "test/CMakeFiles/test_calibration.dir/calibration/test_fix_audit.cc.o" "gcc" "test/CMakeFiles/test_calibration.dir/calibration/test_fix_audit.cc.o.d"
  "/work/main/test/calibration/test_odometer_delay.cc" "test/CMakeFiles/test_calibration.dir/calibration/test_odometer_delay.cc.o" "gcc" "test/CMakeFiles/test_calibration.dir/calibration/test_odometer_delay.cc.o.d"
  "/work/main/test/calibration/test_reinitialization_prior.cc" "test/CMakeFiles/test_calibration.dir/calibration/test_reinitialization_prior.cc.o" "gcc" "test/CMakeFiles/test_calibration.dir/calibration/test_reinitialization_prior.cc.o.d"
  "/work/main/test/calibration/test_rejection_share.cc" "test/CMakeFiles/test_calibration.dir/calibration/test_rejection_share.cc.o" "gcc" "test/CMakeFiles/test_calibration.dir/calibration/test_rejection_share.cc.o.d"
  "/work/main/test/calibration/test_weak_directions.cc" "test/CMakeFiles/test_calibration.dir/calibration/test_weak_directions.cc.o" "gcc" "test/CMakeFiles/test_calibration.dir/calibration/test_weak_directions.cc.o.d"
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
