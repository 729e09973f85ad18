# The GL loader is generated at configure time by Debian's glad 2 (python3-glad), offline
# thanks to --reproducible. Nothing generated is committed.
find_program(GLAD_EXECUTABLE glad PATHS /usr/bin NO_DEFAULT_PATH)
find_program(GLAD_EXECUTABLE glad)
if(NOT GLAD_EXECUTABLE)
  message(FATAL_ERROR "glad not found: install python3-glad (./run.sh does it for you)")
endif()
set(GLAD_OUT ${CMAKE_BINARY_DIR}/glad)
set(GLAD_EXTENSIONS
    GL_ARB_pipeline_statistics_query,GL_ARB_clip_control,GL_KHR_debug,GL_ARB_timer_query)
set(GLAD_STAMP "${GLAD_EXECUTABLE} gl:core=4.5 ${GLAD_EXTENSIONS}")
if(NOT EXISTS ${GLAD_OUT}/src/gl.c OR NOT "${GLAD_STAMP}" STREQUAL "${GLAD_LAST_STAMP}")
  message(STATUS "Generating the GL loader with glad")
  execute_process(
    COMMAND ${GLAD_EXECUTABLE} --quiet --reproducible --api gl:core=4.5
            --extensions ${GLAD_EXTENSIONS} --out-path ${GLAD_OUT} c --loader
    RESULT_VARIABLE glad_result OUTPUT_VARIABLE glad_log ERROR_VARIABLE glad_log)
  if(NOT glad_result EQUAL 0)
    message(FATAL_ERROR "glad failed (${glad_result}):\n${glad_log}")
  endif()
  set(GLAD_LAST_STAMP "${GLAD_STAMP}" CACHE INTERNAL "")
endif()
add_library(glad STATIC ${GLAD_OUT}/src/gl.c)
target_include_directories(glad SYSTEM PUBLIC ${GLAD_OUT}/include)
set_target_properties(glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
