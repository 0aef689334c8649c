# Runs EXE on STUDY; checks the exit status and output the study's header asks for.
# PREFIX (optional, a list): a command that runs EXE (prlimit --as=...).
# EXPECT_NO_OUTPUT (optional): a REGEX the output must not match.
if(NOT DEFINED EXPECT_EXIT)
  file(STRINGS ${STUDY} header LIMIT_COUNT 5)
  foreach(line ${header})
    if(line MATCHES "^(--|#) expect-exit: ([0-9]+)")  # a Lua study or a command file
      set(EXPECT_EXIT ${CMAKE_MATCH_2})
    elseif(line MATCHES "^(--|#) expect-output: (.*)$")
      set(EXPECT_OUTPUT "${CMAKE_MATCH_2}")
    endif()
  endforeach()
endif()
execute_process(COMMAND ${PREFIX} ${EXE} --output-dir ${OUT} ${STUDY}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT "${status}" STREQUAL "${EXPECT_EXIT}")
  message(FATAL_ERROR "exit status ${status}, expected ${EXPECT_EXIT}")
endif()
if(DEFINED EXPECT_OUTPUT AND NOT "${out}${err}" MATCHES "${EXPECT_OUTPUT}")
  message(FATAL_ERROR "output does not match: ${EXPECT_OUTPUT}")
endif()
if(DEFINED EXPECT_NO_OUTPUT AND "${out}${err}" MATCHES "${EXPECT_NO_OUTPUT}")
  message(FATAL_ERROR "output matches what it must not: ${EXPECT_NO_OUTPUT}")
endif()
if("${out}${err}" MATCHES "runtime error:|AddressSanitizer|LeakSanitizer")
  message(FATAL_ERROR "sanitizer report")
endif()
