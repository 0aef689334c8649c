# Runs the .export in DIR as code_aster's runner would, on a copy in OUT (the
# .export writes its result file beside itself): its two command files in one
# run (POURSUITE), the mesh it lists (../rectangle_4x1.mail) bound to unit 20, the
# checks' .resu written where its `F resu ... R 8` line says.
file(REMOVE_RECURSE ${OUT})
file(COPY ${DIR} DESTINATION ${OUT})
file(COPY ${MESH} DESTINATION ${OUT})
get_filename_component(name ${DIR} NAME)
execute_process(COMMAND ${EXE} ${OUT}/${name}/traction.export
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT "${status}" STREQUAL "0")
  message(FATAL_ERROR "exit status ${status}, expected 0")
endif()
if(NOT "${out}${err}" MATCHES "<I> checks: 2 OK, 0 NOOK")
  message(FATAL_ERROR "the two checks of the second command file did not run")
endif()
if(NOT EXISTS ${OUT}/${name}/traction/traction.checks)
  message(FATAL_ERROR "no .checks file in the output folder (the .export's name beside it)")
endif()
file(STRINGS ${OUT}/${name}/traction/traction.checks checks)
list(LENGTH checks count)
if(NOT count EQUAL 4 OR NOT "${checks}" MATCHES "^OK\tTEST_RESU\t[^;]*traction_part2.lua:6\t[^;]*;OK\tTEST_RESU\t")
  message(FATAL_ERROR "traction.checks: '${checks}', expected four OK comparisons (two checks with a reference) at traction_part2.lua:6")
endif()
file(READ ${OUT}/${name}/traction.resu resu)
if(NOT resu MATCHES "<I> checks: 2 OK, 0 NOOK")
  message(FATAL_ERROR "the R file traction.resu does not hold the checks")
endif()
