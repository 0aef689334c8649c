# Runs EXE on STUDY_A and STUDY_B and requires the output lines that match
# PATTERN (a regular expression: for SSNP150 B the per-mesh errors and the rates,
# printed with 7 significant digits) to be the same, in the same order, in both.
foreach(which A B)
  execute_process(COMMAND ${EXE} --output-dir ${OUT}/${which} ${STUDY_${which}}
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${STUDY_${which}}: exit status ${status}\n${out}${err}")
  endif()
  string(REPLACE ";" "," out "${out}")
  string(REPLACE "\n" ";" lines_${which} "${out}")
  list(FILTER lines_${which} INCLUDE REGEX "${PATTERN}")
  list(LENGTH lines_${which} n_${which})
endforeach()
if(n_A LESS MIN_LINES)
  message(FATAL_ERROR "${STUDY_A} printed ${n_A} lines matching ${PATTERN}, expected at least ${MIN_LINES}")
endif()
if(NOT "${lines_A}" STREQUAL "${lines_B}")
  string(REPLACE ";" "\n" a "${lines_A}")
  string(REPLACE ";" "\n" b "${lines_B}")
  message(FATAL_ERROR "the studies differ:\n${STUDY_A}:\n${a}\n${STUDY_B}:\n${b}")
endif()
string(REPLACE ";" "\n" a "${lines_A}")
message("identical in both studies:\n${a}")
