# Checks that the ctest entries and the Catch2 test cases map one to one: every entry of CTEST_DIR
# runs exactly one test case of its executable, the one it is named after, and every test case of
# every test executable (one per SOURCES_DIR/test_*.cpp, in EXECUTABLE_DIR) has exactly one entry.
# A name that catch_discover_tests cannot carry (a ';' splits it into two entries whose filters
# match nothing) or that Catch2's test spec reads as more than a name (a ',' left unescaped, a
# leading '~') breaks the map: the test case then never runs, and ctest used to call it Passed.
#
# Input: CTEST_COMMAND, CTEST_DIR, EXECUTABLE_DIR, SOURCES_DIR. Prints one line per defect to
# standard error and fails when there is one; prints the counts otherwise. An entry is named
# "test_x:<test case>" (catch_discover_tests's TEST_PREFIX), except python_module (pytest) and
# rooms and layers (.ci/rooms.py, .ci/layers.py).
include("${CMAKE_CURRENT_LIST_DIR}/CatchNameList.cmake")
execute_process(COMMAND "${CTEST_COMMAND}" --show-only=json-v1 WORKING_DIRECTORY "${CTEST_DIR}"
                OUTPUT_VARIABLE json RESULT_VARIABLE result ERROR_VARIABLE errors)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "ctest --show-only=json-v1 in ${CTEST_DIR} failed (${result}): ${errors}")
endif()
string(JSON tests GET "${json}" tests)
string(JSON entry_count LENGTH "${tests}")

set(defects "")
set(entries_run 0)
if(entry_count GREATER 0)
  math(EXPR last "${entry_count} - 1")
  foreach(i RANGE ${last})
    string(JSON entry GET "${tests}" ${i})
    string(JSON entry_name GET "${entry}" name)
    # The entries that are not Catch2 test cases: the Python module's pytest suite
    # (python/CMakeLists.txt), the include-cycle and the layers checks (tests/CMakeLists.txt).
    if(entry_name STREQUAL "python_module" OR entry_name STREQUAL "rooms" OR
       entry_name STREQUAL "layers")
      continue()
    endif()
    string(JSON argc ERROR_VARIABLE no_command LENGTH "${entry}" command)
    if(no_command OR argc LESS 2)
      string(APPEND defects "entry '${entry_name}': no test executable and filter\n")
      continue()
    endif()
    string(JSON executable GET "${entry}" command 0)
    get_filename_component(executable_name "${executable}" NAME)
    set(arguments "")
    math(EXPR last_argument "${argc} - 1")
    foreach(k RANGE 1 ${last_argument})
      string(JSON argument GET "${entry}" command ${k})
      list(APPEND arguments "${argument}")
    endforeach()
    execute_process(COMMAND "${executable}" ${arguments} --list-test-names-only
                    OUTPUT_VARIABLE listed RESULT_VARIABLE result ERROR_QUIET)
    string(REGEX REPLACE "\n$" "" listed "${listed}")
    set(expected_prefix "${executable_name}:")
    string(FIND "${entry_name}" "${expected_prefix}" at)
    string(LENGTH "${expected_prefix}" prefix_length)
    if(NOT at EQUAL 0)
      string(APPEND defects "entry '${entry_name}': not named '${expected_prefix}<test case>'\n")
    elseif(listed STREQUAL "")
      string(APPEND defects "entry '${entry_name}': its filter selects no test case\n")
    elseif(listed MATCHES "\n")
      string(REPLACE "\n" " | " listed "${listed}")
      string(APPEND defects "entry '${entry_name}': its filter selects several: ${listed}\n")
    else()
      string(SUBSTRING "${entry_name}" ${prefix_length} -1 case_name)
      if(NOT listed STREQUAL case_name)
        string(APPEND defects "entry '${entry_name}': its filter selects '${listed}'\n")
      else()
        string(MD5 key "${executable_name}\n${case_name}")
        if(NOT DEFINED entries_of_${key})
          set(entries_of_${key} 0)
        endif()
        math(EXPR entries_of_${key} "${entries_of_${key}} + 1")
        math(EXPR entries_run "${entries_run} + 1")
      endif()
    endif()
  endforeach()
endif()

file(GLOB sources "${SOURCES_DIR}/test_*.cpp")
set(cases 0)
foreach(source IN LISTS sources)
  get_filename_component(executable_name "${source}" NAME_WE)
  set(executable "${EXECUTABLE_DIR}/${executable_name}")
  if(NOT EXISTS "${executable}")
    string(APPEND defects "${executable_name}: not built (${executable})\n")
    continue()
  endif()
  execute_process(COMMAND "${executable}" --list-test-names-only OUTPUT_VARIABLE names
                  RESULT_VARIABLE result ERROR_QUIET)
  if(result LESS 1)
    string(APPEND defects "${executable_name}: lists no test case\n")
  endif()
  catch_name_list("${names}" names)
  foreach(name IN LISTS names)
    catch_name_unmask("${name}" name)
    math(EXPR cases "${cases} + 1")
    string(MD5 key "${executable_name}\n${name}")
    if(NOT DEFINED entries_of_${key})
      string(APPEND defects "${executable_name}: '${name}' has no ctest entry that runs it\n")
    elseif(NOT entries_of_${key} EQUAL 1)
      string(APPEND defects
             "${executable_name}: '${name}' is run by ${entries_of_${key}} ctest entries\n")
    endif()
  endforeach()
endforeach()

if(NOT defects STREQUAL "")
  # NOTICE prints the lines as they are (FATAL_ERROR would rewrap them).
  message(NOTICE "${defects}")
  message(FATAL_ERROR "ctest entries and test cases do not map one to one (above)")
endif()
message(STATUS "${entry_count} ctest entries, ${cases} test cases: each entry runs its one test "
               "case, each test case has one entry")
