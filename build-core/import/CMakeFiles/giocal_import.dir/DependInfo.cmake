
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/import/bag_dataset.cc" "import/CMakeFiles/giocal_import.dir/bag_dataset.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/bag_dataset.cc.o.d"
  "/work/main/import/bag_stamps.cc" "import/CMakeFiles/giocal_import.dir/bag_stamps.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/bag_stamps.cc.o.d"
  "/work/main/import/beidou_d1.cc" "import/CMakeFiles/giocal_import.dir/beidou_d1.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/beidou_d1.cc.o.d"
  "/work/main/import/beidou_d2.cc" "import/CMakeFiles/giocal_import.dir/beidou_d2.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/beidou_d2.cc.o.d"
  "/work/main/import/beidou_nav.cc" "import/CMakeFiles/giocal_import.dir/beidou_nav.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/beidou_nav.cc.o.d"
  "/work/main/import/bit_buffer.cc" "import/CMakeFiles/giocal_import.dir/bit_buffer.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/bit_buffer.cc.o.d"
  "/work/main/import/galileo_inav.cc" "import/CMakeFiles/giocal_import.dir/galileo_inav.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/galileo_inav.cc.o.d"
  "/work/main/import/gnss_comm_messages.cc" "import/CMakeFiles/giocal_import.dir/gnss_comm_messages.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/gnss_comm_messages.cc.o.d"
  "/work/main/import/gps_lnav.cc" "import/CMakeFiles/giocal_import.dir/gps_lnav.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/gps_lnav.cc.o.d"
  "/work/main/import/i2nav_text.cc" "import/CMakeFiles/giocal_import.dir/i2nav_text.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/i2nav_text.cc.o.d"
  "/work/main/import/observation_log.cc" "import/CMakeFiles/giocal_import.dir/observation_log.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/observation_log.cc.o.d"
  "/work/main/import/rawx_decoder.cc" "import/CMakeFiles/giocal_import.dir/rawx_decoder.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/rawx_decoder.cc.o.d"
  "/work/main/import/ros1_bag.cc" "import/CMakeFiles/giocal_import.dir/ros1_bag.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/ros1_bag.cc.o.d"
  "/work/main/import/ros2_bag.cc" "import/CMakeFiles/giocal_import.dir/ros2_bag.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/ros2_bag.cc.o.d"
  "/work/main/import/ros_builtin_definitions.cc" "import/CMakeFiles/giocal_import.dir/ros_builtin_definitions.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/ros_builtin_definitions.cc.o.d"
  "/work/main/import/ros_message.cc" "import/CMakeFiles/giocal_import.dir/ros_message.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/ros_message.cc.o.d"
  "/work/main/import/ros_schema.cc" "import/CMakeFiles/giocal_import.dir/ros_schema.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/ros_schema.cc.o.d"
  "/work/main/import/ublox_messages.cc" "import/CMakeFiles/giocal_import.dir/ublox_messages.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/ublox_messages.cc.o.d"
  "/work/main/import/ubx_log.cc" "import/CMakeFiles/giocal_import.dir/ubx_log.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/ubx_log.cc.o.d"
  "/work/main/import/ubx_signals.cc" "import/CMakeFiles/giocal_import.dir/ubx_signals.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/ubx_signals.cc.o.d"
  "/work/main/import/ubx_stream.cc" "import/CMakeFiles/giocal_import.dir/ubx_stream.cc.o" "gcc" "import/CMakeFiles/giocal_import.dir/ubx_stream.cc.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build-core/common/CMakeFiles/giocal_common.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
