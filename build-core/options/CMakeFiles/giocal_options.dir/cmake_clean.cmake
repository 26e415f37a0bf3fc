file(REMOVE_RECURSE
  "CMakeFiles/giocal_options.dir/fgo_options.cc.o"
  "CMakeFiles/giocal_options.dir/fgo_options.cc.o.d"
  "CMakeFiles/giocal_options.dir/giocal_config.cc.o"
  "CMakeFiles/giocal_options.dir/giocal_config.cc.o.d"
  "libgiocal_options.a"
  "libgiocal_options.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/giocal_options.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
