# The libFuzzer target for the scene loader and validator (clang only; built by scripts/fuzz.sh).
# Hooked into the top-level project without editing it: scripts/fuzz.sh passes this file as
# CMAKE_PROJECT_INCLUDE, which runs right after project(); the target is defined at the end of the
# top-level CMakeLists.txt (cmake_language DEFER), once the stage libraries exist. The script compiles the
# project with -fsanitize=fuzzer-no-link,address,undefined; only this executable links libFuzzer's driver.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "fuzz/ needs clang (libFuzzer): configure with CXX=clang++ (see scripts/fuzz.sh)")
endif()

function(sl_add_fuzz_targets)
  # sl_simulation for the start conversion (initialStateFromSpec, validateInitialState): an accepted scene
  # must give a start the simulation takes.
  add_executable(scene_fuzzer ${CMAKE_SOURCE_DIR}/fuzz/scene_fuzzer.cpp)
  target_link_libraries(scene_fuzzer PRIVATE sl_scene sl_simulation)
  target_link_options(scene_fuzzer PRIVATE -fsanitize=fuzzer)
endfunction()
cmake_language(DEFER DIRECTORY ${CMAKE_SOURCE_DIR} CALL sl_add_fuzz_targets)
