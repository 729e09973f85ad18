# One lesson = one directory with main.cpp and its shaders, and optionally sweep.cpp, its
# time-vs-error sweep for bench_sweep (SHADOWS_SWEEP). The lesson code is an object library so
# tests and the bench can drive the same code in-process; the executable adds the runner's main.
# sweep.cpp goes into the same object library: wherever the lesson is linked, its sweep comes
# with it (bench_sweep runs it, lesson_tests checks its settings against the lesson's
# parameters), and the lesson binary carries a few unused bytes instead of a second list of
# what belongs to a lesson.
# A lesson that runs others inside it (lesson 16; common/lesson/hosted_lesson.hpp) names them in
# its hosts.txt, one a line: its binary links their code, each with its own LESSON_DIR.
function(hosted_objects name suffix out)
  set(objects)
  if(EXISTS ${CMAKE_SOURCE_DIR}/${name}/hosts.txt)
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/${name}/hosts.txt)
    file(STRINGS ${CMAKE_SOURCE_DIR}/${name}/hosts.txt hosted REGEX "^[0-9][0-9]_")
    foreach(h IN LISTS hosted)
      list(APPEND objects $<TARGET_OBJECTS:${h}_lesson${suffix}>)
    endforeach()
  endif()
  set(${out} ${objects} PARENT_SCOPE)
endfunction()

function(add_lesson name)
  # A glob, so that a sweep.cpp added later is noticed by the next build, as a new lesson is.
  file(GLOB sweep CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/${name}/sweep.cpp)
  add_library(${name}_lesson OBJECT ${name}/main.cpp ${sweep})
  target_link_libraries(${name}_lesson PUBLIC shadows_common)
  target_compile_options(${name}_lesson PRIVATE ${SHADOWS_WARNINGS})
  target_compile_definitions(${name}_lesson
    PRIVATE LESSON_DIR="${CMAKE_SOURCE_DIR}/${name}" LESSON_NAME="${name}")
  hosted_objects(${name} "" hosted)
  add_executable(${name} $<TARGET_OBJECTS:${name}_lesson> ${hosted})
  target_link_libraries(${name} PRIVATE shadows_common shadows_main)
  set_property(GLOBAL APPEND PROPERTY SHADOWS_LESSONS ${name})
endfunction()

# The same lesson for an extra flavour (SHADOWS_EXTRA_FLAVOURS): its code against that
# flavour's common/, the binary as build/<flavour>/<lesson>. No sweep: only the primary
# flavour's benchmark runs them.
function(add_flavour_lesson name flavour suffix)
  add_library(${name}_lesson${suffix} OBJECT ${name}/main.cpp)
  target_link_libraries(${name}_lesson${suffix} PUBLIC shadows_common${suffix})
  target_compile_options(${name}_lesson${suffix} PRIVATE ${SHADOWS_WARNINGS})
  target_compile_definitions(${name}_lesson${suffix}
    PRIVATE LESSON_DIR="${CMAKE_SOURCE_DIR}/${name}" LESSON_NAME="${name}")
  hosted_objects(${name} ${suffix} hosted)
  add_executable(${name}${suffix} $<TARGET_OBJECTS:${name}_lesson${suffix}> ${hosted})
  target_link_libraries(${name}${suffix} PRIVATE shadows_common${suffix} shadows_main${suffix})
  set_target_properties(${name}${suffix} PROPERTIES OUTPUT_NAME ${name}
                        RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/${flavour})
endfunction()

# A program scripts/bundle.sh ships: it finds the libraries copied beside it (bundle/lib) by
# an $ORIGIN rpath, inherited by the libraries it loads (DT_RPATH, not DT_RUNPATH, so
# libglfw finds the bundle's libX11 too). In the build tree bin/../lib does not exist, so the
# system's libraries are used as before.
function(shadows_bundled target)
  set_target_properties(${target} PROPERTIES BUILD_RPATH "\$ORIGIN/../lib")
  target_link_options(${target} PRIVATE LINKER:--disable-new-dtags)
endfunction()
