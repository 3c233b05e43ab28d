# Sets each discovered Catch2 test's ctest LABELS from its tags, so that `ctest -L claim` runs the
# tests tagged [claim]. Catch2 v2's catch_discover_tests has no ADD_TAGS_AS_LABELS (a Catch2 v3
# option): run after the build, this script asks the test executable for its tags (--list-tags)
# and, for each tag, for the tests that carry it (--list-test-names-only "[tag]"), then writes
# set_tests_properties(... LABELS ...) to LABELS_FILE, which ctest includes after the tests file.
#
# Input: TEST_EXECUTABLE, TEST_PREFIX (as given to catch_discover_tests), LABELS_FILE.
execute_process(COMMAND "${TEST_EXECUTABLE}" --list-tags OUTPUT_VARIABLE tags_output
                RESULT_VARIABLE result)
if(result LESS 0)
  message(FATAL_ERROR "CatchTagLabels: ${TEST_EXECUTABLE} --list-tags failed: ${result}")
endif()
# Lines look like "   3  [claim]"; hidden ([.]) and special ([!mayfail]) tags are not labels.
string(REGEX MATCHALL "[0-9]+  \\[[^]\n]+\\]" tag_lines "${tags_output}")
set(tests_seen)
foreach(tag_line IN LISTS tag_lines)
  string(REGEX REPLACE "^[0-9]+  \\[([^]]+)\\]$" "\\1" tag "${tag_line}")
  if(tag MATCHES "^[.!]")
    continue()
  endif()
  execute_process(COMMAND "${TEST_EXECUTABLE}" "[${tag}]" --list-test-names-only
                  OUTPUT_VARIABLE names RESULT_VARIABLE result)
  if(result LESS 0)
    message(FATAL_ERROR "CatchTagLabels: ${TEST_EXECUTABLE} [${tag}] failed: ${result}")
  endif()
  string(REPLACE "\n" ";" names "${names}")
  foreach(name IN LISTS names)
    if(name STREQUAL "")
      continue()
    endif()
    string(MD5 key "${name}")
    if(NOT DEFINED labels_${key})
      list(APPEND tests_seen "${key}")
      set(name_${key} "${name}")
    endif()
    list(APPEND labels_${key} "${tag}")
  endforeach()
endforeach()
set(script "")
foreach(key IN LISTS tests_seen)
  list(SORT labels_${key})
  string(APPEND script "set_tests_properties([==[${TEST_PREFIX}${name_${key}}]==] "
         "PROPERTIES LABELS \"${labels_${key}}\")\n")
endforeach()
file(WRITE "${LABELS_FILE}" "${script}")
