# The layers of common/ only go down (docs/ARCHITECTURE.md): every #include "folder/file" in
# common/<layer>/ and in the lessons must name a folder the layer may use. Run as
#   cmake -DROOT=<source dir> -P tests/layers.cmake
# It prints each include that crosses a layer the wrong way and fails when there is one.
#
#   core    plain C++ every layer uses: text, JSON, files, images, arguments, parameters, scene
#   math    the seeds' formulas in plain GLM (no GL)           uses core
#   truth   the ray-traced reference and the error metrics      uses core, math   (no GL)
#   gl      the API, its flavours, programs, contexts, timers   uses core
#   lesson  what a lesson's main.cpp sees (Lesson, Frame)       uses core, math, gl, and of
#                                                               truth only truth_types.hpp
#   shadow  the techniques lessons share (maps, light views)    uses core, math, gl, lesson
#   run     the runner: window, headless, panel, report, truth  uses all of them
#   NN_*    a lesson                                            uses core, math, gl, lesson, shadow
# "shaders/..." (GLSL that C++ mirrors) may be included from anywhere.
cmake_minimum_required(VERSION 3.20)
set(allowed_core core)
set(allowed_math core math)
set(allowed_truth core math truth)
set(allowed_gl core gl)
set(allowed_lesson core math truth gl lesson)
set(allowed_shadow core math gl lesson shadow)
set(allowed_run core math truth gl lesson shadow run)
set(allowed_lessons core math gl lesson shadow)
set(layers core math truth gl lesson shadow run)

if(NOT ROOT)
  message(FATAL_ERROR "layers.cmake: -DROOT=<source dir> is required")
endif()

set(crossings 0)
set(checked 0)
# check(FILE LAYER): the includes of FILE against allowed_LAYER.
function(check file layer)
  file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]+\"")
  get_filename_component(dir ${file} DIRECTORY)
  file(RELATIVE_PATH shown ${ROOT} ${file})
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([^\"]+)\".*" "\\1" included "${line}")
    if(included MATCHES "^shaders/")
      continue()
    endif()
    if(included MATCHES "^([a-z]+)/")
      set(folder ${CMAKE_MATCH_1})
      if(NOT folder IN_LIST layers)
        message("${shown}: #include \"${included}\": ${folder}/ is not a folder of common/")
        math(EXPR crossings "${crossings} + 1")
      elseif(NOT folder IN_LIST allowed_${layer})
        message("${shown}: #include \"${included}\": ${layer} may not use ${folder}/ "
                "(it may use: ${allowed_${layer}})")
        math(EXPR crossings "${crossings} + 1")
      elseif(layer STREQUAL "lesson" AND folder STREQUAL "truth" AND
             NOT included STREQUAL "truth/truth_types.hpp")
        # What a lesson sees may hand the truth its data, never reach its tracer.
        message("${shown}: #include \"${included}\": lesson/ takes the truth's types only "
                "(truth/truth_types.hpp), not the tracer")
        math(EXPR crossings "${crossings} + 1")
      endif()
    elseif(NOT EXISTS ${dir}/${included})
      # A bare name must be a file next to the includer (a lesson's own header); anything of
      # common/ is named with its folder, so the layer is visible where it is used.
      message("${shown}: #include \"${included}\": name the folder of common/ it is in")
      math(EXPR crossings "${crossings} + 1")
    endif()
  endforeach()
  math(EXPR checked "${checked} + 1")
  set(crossings ${crossings} PARENT_SCOPE)
  set(checked ${checked} PARENT_SCOPE)
endfunction()

foreach(layer IN LISTS layers)
  file(GLOB_RECURSE files ${ROOT}/common/${layer}/*.cpp ${ROOT}/common/${layer}/*.hpp)
  foreach(f IN LISTS files)
    check(${f} ${layer})
  endforeach()
endforeach()
file(GLOB stray ${ROOT}/common/*.cpp ${ROOT}/common/*.hpp)
foreach(f IN LISTS stray)
  file(RELATIVE_PATH shown ${ROOT} ${f})
  message("${shown}: in no layer: move it into the folder of common/ it belongs to")
  math(EXPR crossings "${crossings} + 1")
endforeach()
file(GLOB lesson_files ${ROOT}/[0-9][0-9]_*/*.cpp ${ROOT}/[0-9][0-9]_*/*.hpp)
foreach(f IN LISTS lesson_files)
  check(${f} lessons)
endforeach()

if(crossings GREATER 0)
  message(FATAL_ERROR "layers: ${crossings} include(s) cross a layer the wrong way")
endif()
message("layers: ok, ${checked} files, every include goes down")
