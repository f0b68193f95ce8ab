file(REMOVE_RECURSE
  "CMakeFiles/simulate.dir/src/tools/simulate_main.cpp.o"
  "CMakeFiles/simulate.dir/src/tools/simulate_main.cpp.o.d"
  "simulate"
  "simulate.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/simulate.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
