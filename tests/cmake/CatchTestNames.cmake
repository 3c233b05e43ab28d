# Fails the build of a test executable when one of its test case names cannot become a ctest entry
# that runs exactly that test case. catch_discover_tests reads the names as a CMake list, so a ';'
# splits a name into two entries whose filters match nothing (the test case then never runs), and
# it escapes only ',', '[' and ']' for Catch2's test spec, in which '\' escapes, '*' at either end
# is a wildcard, and a leading '~', '"', '#' or blank changes what the filter means.
# tests/cmake/CtestEntries.cmake checks the whole map after discovery (test_ctest_entries).
#
# Input: TEST_EXECUTABLE.
include("${CMAKE_CURRENT_LIST_DIR}/CatchNameList.cmake")
execute_process(COMMAND "${TEST_EXECUTABLE}" --list-test-names-only OUTPUT_VARIABLE names
                RESULT_VARIABLE result)
if(result LESS 0)
  message(FATAL_ERROR "CatchTestNames: ${TEST_EXECUTABLE} --list-test-names-only failed: ${result}")
endif()
set(bad "")
catch_name_list("${names}" names)
foreach(name IN LISTS names)
  catch_name_unmask("${name}" name)
  if(name MATCHES "[;\\\\]" OR name MATCHES "^[ ~\"#*]" OR name MATCHES "[ *]$")
    string(APPEND bad "  \"${name}\"\n")
  endif()
endforeach()
if(NOT bad STREQUAL "")
  message(FATAL_ERROR
          "${TEST_EXECUTABLE}: test case names that cannot be a ctest entry of their own (no ';' "
          "or '\\'; no leading blank, '~', '\"', '#' or '*'; no trailing blank or '*'):\n${bad}")
endif()
