# common/ stays readable (issue 33, issue 57): no file of common/ past MAX_FILE lines, no class
# or struct declaration past MAX_CLASS lines, no function body past MAX_FUNCTION lines. Run as
#   cmake -DROOT=<source dir> -P tests/sizes.cmake
# It prints each file or declaration over its limit and fails when there is one. When one
# grows past them, split it along a seam (docs/ARCHITECTURE.md) rather than raise the limits.
cmake_minimum_required(VERSION 3.20)
set(MAX_FILE 470)   # "about 450"
set(MAX_CLASS 120)  # "about 100": JsonWriter's inline writers are the longest today
set(MAX_FUNCTION 90)  # "about 80": a longer one has named sections waiting to be functions
if(NOT ROOT)
  message(FATAL_ERROR "sizes.cmake: -DROOT=<source dir> is required")
endif()

set(over 0)
set(checked 0)
file(GLOB_RECURSE files ${ROOT}/common/*.cpp ${ROOT}/common/*.hpp)
foreach(f IN LISTS files)
  file(RELATIVE_PATH shown ${ROOT} ${f})
  # The text as a list of its lines, empty ones included: ; [ ] would split or join CMake's
  # list elements, so they go first (no check looks at them).
  file(READ ${f} text)
  string(REGEX REPLACE "[];[]" "_" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  list(LENGTH lines count)
  math(EXPR count "${count} - 1")  # the last newline ends the last line
  if(count GREATER MAX_FILE)
    message("${shown}: ${count} lines (at most ${MAX_FILE}): split it along a seam")
    math(EXPR over "${over} + 1")
  endif()
  # A declaration opens at column 0 ("class Name ... {") and closes at column 0 ("};"). A
  # function's signature starts at column 0 (a line that is not a declaration ending in ";")
  # and its body closes with a "}" alone at column 0.
  set(line_number 0)
  set(open "")
  set(signature "")
  foreach(line IN LISTS lines)
    math(EXPR line_number "${line_number} + 1")
    if(line MATCHES "^(namespace|class|struct|enum|union|extern|template|using)[ {<]")
      set(signature "")
    elseif(line MATCHES "^[A-Za-z_]")
      if(line MATCHES "_$" OR line MATCHES ",$")  # a declaration (";") or a table's row
        set(signature "")
      else()
        set(signature ${line_number})
        string(REGEX REPLACE "\\(.*" "" function "${line}")
      endif()
    elseif(line STREQUAL "}" AND NOT signature STREQUAL "")
      math(EXPR length "${line_number} - ${signature} + 1")
      if(length GREATER MAX_FUNCTION)
        message("${shown}:${signature}: ${function} runs ${length} lines (at most "
                "${MAX_FUNCTION}): give its sections names of their own")
        math(EXPR over "${over} + 1")
      endif()
      set(signature "")
    endif()
    if(open STREQUAL "" AND line MATCHES "^(class|struct) ([A-Za-z_][A-Za-z_0-9]*).*{$")
      set(open ${CMAKE_MATCH_2})
      set(opened ${line_number})
    elseif(NOT open STREQUAL "" AND line MATCHES "^}_")
      math(EXPR length "${line_number} - ${opened} + 1")
      if(length GREATER MAX_CLASS)
        message("${shown}:${opened}: ${open}'s declaration runs ${length} lines (at most "
                "${MAX_CLASS}): give a part of it an object of its own")
        math(EXPR over "${over} + 1")
      endif()
      set(open "")
    endif()
  endforeach()
  math(EXPR checked "${checked} + 1")
endforeach()

if(over GREATER 0)
  message(FATAL_ERROR "sizes: ${over} file(s) or declaration(s) over their limits")
endif()
message("sizes: ok, ${checked} files of common/")
