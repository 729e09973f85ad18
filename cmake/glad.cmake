# The GL loader is generated at configure time by Debian's glad 2 (python3-glad), offline
# thanks to --reproducible, one per build flavour (SHADOWS_GL): each API gets a loader with only
# its own functions, so a call above the flavour's version does not compile. Extensions listed
# here are optional: the code checks them at run time (common/gl/caps.cpp). Nothing generated is
# committed.
find_program(GLAD_EXECUTABLE glad PATHS /usr/bin NO_DEFAULT_PATH)
find_program(GLAD_EXECUTABLE glad)
if(NOT GLAD_EXECUTABLE)
  message(FATAL_ERROR "glad not found: install python3-glad (./run.sh does it for you)")
endif()

# shadows_glad(FLAVOUR TARGET): a static library TARGET with FLAVOUR's loader.
function(shadows_glad flavour target)
  if(flavour STREQUAL "gl45")
    set(api gl:core=4.5)
    set(extensions
        GL_ARB_pipeline_statistics_query,GL_ARB_clip_control,GL_KHR_debug,GL_ARB_timer_query)
    set(out ${CMAKE_BINARY_DIR}/glad)
    set(source gl.c)
    set(loader --loader)
  elseif(flavour STREQUAL "gl41")
    set(api gl:core=4.1)
    set(extensions GL_ARB_pipeline_statistics_query,GL_KHR_debug)
    set(out ${CMAKE_BINARY_DIR}/glad-gl41)
    set(source gl.c)
    set(loader --loader)
  elseif(flavour STREQUAL "gles30")
    set(api gles2=3.0)
    set(extensions GL_KHR_debug,GL_EXT_color_buffer_float)
    set(out ${CMAKE_BINARY_DIR}/glad-gles30)
    set(source gles2.c)
    set(loader)  # its own loader would want glad's EGL header: ours loads through EGL or GLFW
  else()
    message(FATAL_ERROR "SHADOWS_GL: no flavour '${flavour}' (gl45, gl41 or gles30)")
  endif()
  set(stamp "${GLAD_EXECUTABLE} ${api} ${extensions} ${loader}")
  if(NOT EXISTS ${out}/src/${source} OR NOT "${stamp}" STREQUAL "${GLAD_STAMP_${flavour}}")
    message(STATUS "Generating the ${flavour} loader with glad")
    execute_process(
      COMMAND ${GLAD_EXECUTABLE} --quiet --reproducible --api ${api} --extensions ${extensions}
              --out-path ${out} c ${loader}
      RESULT_VARIABLE glad_result OUTPUT_VARIABLE glad_log ERROR_VARIABLE glad_log)
    if(NOT glad_result EQUAL 0)
      message(FATAL_ERROR "glad failed (${glad_result}):\n${glad_log}")
    endif()
    set(GLAD_STAMP_${flavour} "${stamp}" CACHE INTERNAL "")
  endif()
  add_library(${target} STATIC ${out}/src/${source})
  target_include_directories(${target} SYSTEM PUBLIC ${out}/include)
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()
