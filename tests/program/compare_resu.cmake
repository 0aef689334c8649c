# Runs EXE on STUDY and compares the .resu file it writes with EXPECTED, byte for
# byte, and its .checks file with EXPECTED_CHECKS (where STUDY: stands for the
# study's path as given).
execute_process(COMMAND ${EXE} --output-dir ${OUT} ${STUDY} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
get_filename_component(name ${STUDY} NAME_WE)
file(READ ${OUT}/${name}.resu got)
file(READ ${EXPECTED} want)
if(NOT got STREQUAL want)
  message(FATAL_ERROR "${OUT}/${name}.resu differs from ${EXPECTED} (exit status ${status}):\n${got}")
endif()
if(DEFINED EXPECTED_CHECKS)
  file(READ ${OUT}/${name}.checks got)
  file(READ ${EXPECTED_CHECKS} want)
  string(REPLACE "STUDY:" "${STUDY}:" want "${want}")
  if(NOT got STREQUAL want)
    message(FATAL_ERROR "${OUT}/${name}.checks differs from ${EXPECTED_CHECKS}:\n${got}")
  endif()
endif()
