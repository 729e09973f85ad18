# Read by ctest after the three gtest binaries' lists (their TEST_LIST variables), so their
# tests can carry labels by name, as tests/CMakeLists.txt gives the others (tests/README.md,
# "The suite's budget"):
#   quick      each lesson's goldens, views, parameters, baseline and command line, every unit
#              test: what a change in common/ is checked by first (about a minute and a half,
#              its rebuild included)
#   lessonNN   every test of lesson NN, whatever binary or script runs it
foreach(binary IN ITEMS unit_tests lesson_tests cli_tests)
  if(binary STREQUAL "unit_tests")
    set(area unit)
  elseif(binary STREQUAL "lesson_tests")
    set(area lessons)
  else()
    set(area cli)
  endif()
  foreach(test IN LISTS ${binary}_TESTS)
    set(labels ${area})
    if(area STREQUAL "unit" OR test MATCHES
       "^(Lesson[0-9]+\\.Snapshot|Lessons/EveryLessonCli\\.DefaultHeadlessRun|Lessons/EveryLesson\\.EveryViewRendersWithEverySwitch|Lessons/ParamEffects\\.|Lessons/Baseline\\.|EveryLesson/SwitchThatSavesWork\\.)")
      list(APPEND labels quick)
    endif()
    if(test MATCHES "Lesson([0-9][0-9])")
      list(APPEND labels lesson${CMAKE_MATCH_1})
    elseif(test MATCHES "/([0-9][0-9])_")
      list(APPEND labels lesson${CMAKE_MATCH_1})
    endif()
    set_tests_properties(${test} PROPERTIES LABELS "${labels}")
  endforeach()
endforeach()
