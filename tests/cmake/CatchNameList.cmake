# The names a Catch2 executable prints with --list-test-names-only, read the same way by
# CatchTestNames.cmake and CtestEntries.cmake. A CMake list splits at ';' and not inside [...],
# so the text is split on newlines only with those characters masked:
#   catch_name_list(TEXT OUT)   OUT: the masked names, one per non-empty line;
#   catch_name_unmask(NAME OUT) OUT: one of them as Catch2 printed it.
function(catch_name_list text out)
  string(REPLACE ";" "<semicolon>" text "${text}")
  string(REPLACE "[" "<bracket>" text "${text}")
  string(REPLACE "]" "<close-bracket>" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(names "")
  foreach(line IN LISTS lines)
    if(NOT line STREQUAL "")
      list(APPEND names "${line}")
    endif()
  endforeach()
  set(${out} "${names}" PARENT_SCOPE)
endfunction()

function(catch_name_unmask name out)
  string(REPLACE "<semicolon>" ";" name "${name}")
  string(REPLACE "<bracket>" "[" name "${name}")
  string(REPLACE "<close-bracket>" "]" name "${name}")
  set(${out} "${name}" PARENT_SCOPE)
endfunction()
