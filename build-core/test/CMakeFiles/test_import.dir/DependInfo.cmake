
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/test/import/test_bag_gnss_comm.cc" "test/CMakeFiles/test_import.dir/import/test_bag_gnss_comm.cc.o" "gcc" "test/CMakeFiles/test_import.dir/import/test_bag_gnss_comm.cc.o.d"
  "/work/main/test/import/test_bag_import.cc" "test/CMakeFiles/test_import.dir/import/test_bag_import.cc.o" "gcc" "test/CMakeFiles/test_import.dir/import/test_bag_import.cc.o.d"
  "/work/main/test/import/test_bag_raw_gnss.cc" "test/CMakeFiles/test_import.dir/import/test_bag_raw_gnss.cc.o" "gcc" "test/CMakeFiles/test_import.dir/import/test_bag_raw_gnss.cc.o.d"
  "/work/main/test/import/test_beidou_d2.cc" "test/CMakeFiles/test_import.dir/import/test_beidou_d2.cc.o" "gcc" "test/CMakeFiles/test_import.dir/import/test_beidou_d2.cc.o.d"
  "/work/main/test/import/test_ros2_bag.cc" "test/CMakeFiles/test_import.dir/import/test_ros2_bag.cc.o" "gcc" "test/CMakeFiles/test_import.dir/import/test_ros2_bag.cc.o.d"
  "/work/main/test/import/test_ros_message.cc" "test/CMakeFiles/test_import.dir/import/test_ros_message.cc.o" "gcc" "test/CMakeFiles/test_import.dir/import/test_ros_message.cc.o.d"
  "/work/main/test/import/test_ubx_parts.cc" "test/CMakeFiles/test_import.dir/import/test_ubx_parts.cc.o" "gcc" "test/CMakeFiles/test_import.dir/import/test_ubx_parts.cc.o.d"
  "/work/main/test/import/test_ubx_real.cc" "test/CMakeFiles/test_import.dir/import/test_ubx_real.cc.o" "gcc" "test/CMakeFiles/test_import.dir/import/test_ubx_real.cc.o.d"
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
