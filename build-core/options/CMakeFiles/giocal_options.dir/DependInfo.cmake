
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/options/fgo_options.cc" "options/CMakeFiles/giocal_options.dir/fgo_options.cc.o" "gcc" "options/CMakeFiles/giocal_options.dir/fgo_options.cc.o.d"
  "/work/main/options/giocal_config.cc" "options/CMakeFiles/giocal_options.dir/giocal_config.cc.o" "gcc" "options/CMakeFiles/giocal_options.dir/giocal_config.cc.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build-core/common/CMakeFiles/giocal_common.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
