# The stages of the program and which may use which: the one home of the layering.
#
#   contracts   plain types, the registry of kinds, limits, time grids (uses nothing of ours)
#   linkage     the chain model: chart, kinetic metric (spec sections 1-3)
#   geometry    the shape of the configuration sphere: curvature, bending, stiffness (docs/geometry.md)
#   scene       scene files -> Scene
#   simulation  geodesic methods, integrators, runs
#   analysis    work-precision and stability sweeps
#   inverse     two-point motions, closed geodesics, parallel transport and holonomy of loops
#   frames      scene + runs -> FrameState per frame
#   render      FrameState -> pixels (draw lists on the CPU; gl: OpenGL through EGL or OSMesa)
#   output      pixels -> PNG files + manifest, video
#   cli         the `linkage` command: wires the stages together
#
# Each stage is a static library sl_<stage> whose include path holds only its own folder and, through
# linking, the folders of the stages it may use. An include of any other stage does not compile, and the
# layer test (tests/architecture) checks every #include against this table as well.
set(SL_STAGES contracts linkage geometry scene simulation analysis inverse frames render output cli)
set(SL_USES_contracts "")
set(SL_USES_linkage contracts)
set(SL_USES_geometry contracts linkage)
set(SL_USES_scene contracts linkage)
set(SL_USES_simulation contracts linkage)
set(SL_USES_analysis contracts linkage simulation)
set(SL_USES_inverse contracts linkage geometry simulation)
set(SL_USES_frames contracts linkage geometry scene simulation inverse)
set(SL_USES_render contracts)
set(SL_USES_output contracts)
set(SL_USES_cli contracts linkage geometry scene simulation analysis inverse frames render output)

# The table as a file for the layer test: one line per stage, "stage: used used ...".
set(_layers "")
foreach(stage IN LISTS SL_STAGES)
  string(JOIN " " _uses ${SL_USES_${stage}})
  string(APPEND _layers "${stage}: ${_uses}\n")
endforeach()
file(WRITE "${CMAKE_BINARY_DIR}/layers.txt" "${_layers}")

# sl_stage_include_dir(<stage> <var>): a folder holding only a link named <stage> to src/<stage>, so that
# "<stage>/x.hpp" resolves and no other stage's header does.
function(sl_stage_include_dir stage out)
  set(dir "${CMAKE_BINARY_DIR}/stage-include/${stage}")
  if(NOT EXISTS "${dir}/${stage}")
    file(MAKE_DIRECTORY "${dir}")
    file(CREATE_LINK "${CMAKE_SOURCE_DIR}/src/${stage}" "${dir}/${stage}" SYMBOLIC)
  endif()
  set(${out} "${dir}" PARENT_SCOPE)
endfunction()

# sl_add_stage(<stage> <sources>...): the stage's library, its include folder, and the stages it may use.
# A stage with no sources (contracts headers only would be INTERFACE) still gets a library.
function(sl_add_stage stage)
  if(NOT stage IN_LIST SL_STAGES)
    message(FATAL_ERROR "sl_add_stage: ${stage} is not in SL_STAGES (cmake/Stages.cmake)")
  endif()
  add_library(sl_${stage} STATIC ${ARGN})
  sl_stage_include_dir(${stage} include_dir)
  target_include_directories(sl_${stage} PUBLIC "${include_dir}")
  foreach(used IN LISTS SL_USES_${stage})
    target_link_libraries(sl_${stage} PUBLIC sl_${used})
  endforeach()
endfunction()
