# The libFuzzer target for the scene loader and validator (clang only; built by scripts/fuzz.sh).
# Hooked into the top-level project without editing it: scripts/fuzz.sh passes this file as
# CMAKE_PROJECT_INCLUDE, which runs right after project(); the target is defined at the end of the
# top-level CMakeLists.txt (cmake_language DEFER), once sl_scene exists. The script compiles the whole
# project with -fsanitize=fuzzer-no-link,address,undefined; only this executable links libFuzzer's driver.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "fuzz/ needs clang (libFuzzer): configure with CXX=clang++ (see scripts/fuzz.sh)")
endif()

function(sl_add_fuzz_targets)
  # The start conversion (frames/scene_start.cpp, simulation/initial_state.cpp) is compiled in directly
  # rather than linking sl_frames, which would build the whole simulation stage, nested AutoDiff included.
  add_executable(scene_fuzzer ${CMAKE_SOURCE_DIR}/fuzz/scene_fuzzer.cpp
                 ${CMAKE_SOURCE_DIR}/src/frames/scene_start.cpp
                 ${CMAKE_SOURCE_DIR}/src/simulation/initial_state.cpp)
  target_link_libraries(scene_fuzzer PRIVATE sl_scene)
  target_link_options(scene_fuzzer PRIVATE -fsanitize=fuzzer)
endfunction()
cmake_language(DEFER DIRECTORY ${CMAKE_SOURCE_DIR} CALL sl_add_fuzz_targets)
