# One lesson = one directory with main.cpp and its shaders. The lesson code is an object
# library so tests can drive the same code in-process; the executable adds the runner's main.
function(add_lesson name)
  add_library(${name}_lesson OBJECT ${name}/main.cpp)
  target_link_libraries(${name}_lesson PUBLIC shadows_common)
  target_compile_options(${name}_lesson PRIVATE ${SHADOWS_WARNINGS})
  target_compile_definitions(${name}_lesson
    PRIVATE LESSON_DIR="${CMAKE_SOURCE_DIR}/${name}" LESSON_NAME="${name}")
  add_executable(${name} $<TARGET_OBJECTS:${name}_lesson>)
  target_link_libraries(${name} PRIVATE shadows_common shadows_main)
  set_property(GLOBAL APPEND PROPERTY SHADOWS_LESSONS ${name})
endfunction()
