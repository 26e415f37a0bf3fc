
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/evaluation/calibration_source.cc" "evaluation/CMakeFiles/giocal_evaluation.dir/calibration_source.cc.o" "gcc" "evaluation/CMakeFiles/giocal_evaluation.dir/calibration_source.cc.o.d"
  "/work/main/evaluation/dead_reckoning.cc" "evaluation/CMakeFiles/giocal_evaluation.dir/dead_reckoning.cc.o" "gcc" "evaluation/CMakeFiles/giocal_evaluation.dir/dead_reckoning.cc.o.d"
  "/work/main/evaluation/ideal_imu.cc" "evaluation/CMakeFiles/giocal_evaluation.dir/ideal_imu.cc.o" "gcc" "evaluation/CMakeFiles/giocal_evaluation.dir/ideal_imu.cc.o.d"
  "/work/main/evaluation/observability.cc" "evaluation/CMakeFiles/giocal_evaluation.dir/observability.cc.o" "gcc" "evaluation/CMakeFiles/giocal_evaluation.dir/observability.cc.o.d"
  "/work/main/evaluation/validation.cc" "evaluation/CMakeFiles/giocal_evaluation.dir/validation.cc.o" "gcc" "evaluation/CMakeFiles/giocal_evaluation.dir/validation.cc.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build-core/common/CMakeFiles/giocal_common.dir/DependInfo.cmake"
  "/work/main/build-core/ekf/CMakeFiles/giocal_ekf.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
