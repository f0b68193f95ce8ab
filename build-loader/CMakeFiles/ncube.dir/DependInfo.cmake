
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/src/geometry/polygon.cpp" "CMakeFiles/ncube.dir/src/geometry/polygon.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/geometry/polygon.cpp.o.d"
  "/work/main/src/machine/cost_model.cpp" "CMakeFiles/ncube.dir/src/machine/cost_model.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/machine/cost_model.cpp.o.d"
  "/work/main/src/machine/hypercube.cpp" "CMakeFiles/ncube.dir/src/machine/hypercube.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/machine/hypercube.cpp.o.d"
  "/work/main/src/machine/parameter_file.cpp" "CMakeFiles/ncube.dir/src/machine/parameter_file.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/machine/parameter_file.cpp.o.d"
  "/work/main/src/machine/platform_config.cpp" "CMakeFiles/ncube.dir/src/machine/platform_config.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/machine/platform_config.cpp.o.d"
  "/work/main/src/nodes/node_runtime.cpp" "CMakeFiles/ncube.dir/src/nodes/node_runtime.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/nodes/node_runtime.cpp.o.d"
  "/work/main/src/nodes/radiosity_processor.cpp" "CMakeFiles/ncube.dir/src/nodes/radiosity_processor.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/nodes/radiosity_processor.cpp.o.d"
  "/work/main/src/radiosity/form_factor.cpp" "CMakeFiles/ncube.dir/src/radiosity/form_factor.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/radiosity/form_factor.cpp.o.d"
  "/work/main/src/radiosity/occluders.cpp" "CMakeFiles/ncube.dir/src/radiosity/occluders.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/radiosity/occluders.cpp.o.d"
  "/work/main/src/radiosity/radiosity_engine.cpp" "CMakeFiles/ncube.dir/src/radiosity/radiosity_engine.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/radiosity/radiosity_engine.cpp.o.d"
  "/work/main/src/radiosity/shooter.cpp" "CMakeFiles/ncube.dir/src/radiosity/shooter.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/radiosity/shooter.cpp.o.d"
  "/work/main/src/render/image.cpp" "CMakeFiles/ncube.dir/src/render/image.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/render/image.cpp.o.d"
  "/work/main/src/render/rasterizer.cpp" "CMakeFiles/ncube.dir/src/render/rasterizer.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/render/rasterizer.cpp.o.d"
  "/work/main/src/scene/scene.cpp" "CMakeFiles/ncube.dir/src/scene/scene.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/scene/scene.cpp.o.d"
  "/work/main/src/scene/scene_loader.cpp" "CMakeFiles/ncube.dir/src/scene/scene_loader.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/scene/scene_loader.cpp.o.d"
  "/work/main/src/simulation/result_file.cpp" "CMakeFiles/ncube.dir/src/simulation/result_file.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/simulation/result_file.cpp.o.d"
  "/work/main/src/simulation/simulation.cpp" "CMakeFiles/ncube.dir/src/simulation/simulation.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/simulation/simulation.cpp.o.d"
  "/work/main/src/tools/simulate_options.cpp" "CMakeFiles/ncube.dir/src/tools/simulate_options.cpp.o" "gcc" "CMakeFiles/ncube.dir/src/tools/simulate_options.cpp.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
