
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/tests/form_factor_test.cpp" "CMakeFiles/unit_tests.dir/tests/form_factor_test.cpp.o" "gcc" "CMakeFiles/unit_tests.dir/tests/form_factor_test.cpp.o.d"
  "/work/main/tests/occluders_test.cpp" "CMakeFiles/unit_tests.dir/tests/occluders_test.cpp.o" "gcc" "CMakeFiles/unit_tests.dir/tests/occluders_test.cpp.o.d"
  "/work/main/tests/radiosity_engine_test.cpp" "CMakeFiles/unit_tests.dir/tests/radiosity_engine_test.cpp.o" "gcc" "CMakeFiles/unit_tests.dir/tests/radiosity_engine_test.cpp.o.d"
  "/work/main/tests/render_test.cpp" "CMakeFiles/unit_tests.dir/tests/render_test.cpp.o" "gcc" "CMakeFiles/unit_tests.dir/tests/render_test.cpp.o.d"
  "/work/main/tests/scene_loader_test.cpp" "CMakeFiles/unit_tests.dir/tests/scene_loader_test.cpp.o" "gcc" "CMakeFiles/unit_tests.dir/tests/scene_loader_test.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build-loader/CMakeFiles/ncube.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
