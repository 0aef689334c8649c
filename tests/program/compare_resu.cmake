# Runs EXE on STUDY and compares the .resu file it writes with EXPECTED, byte for byte.
execute_process(COMMAND ${EXE} --output-dir ${OUT} ${STUDY} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
get_filename_component(name ${STUDY} NAME_WE)
file(READ ${OUT}/${name}.resu got)
file(READ ${EXPECTED} want)
if(NOT got STREQUAL want)
  message(FATAL_ERROR "${OUT}/${name}.resu differs from ${EXPECTED} (exit status ${status}):\n${got}")
endif()
