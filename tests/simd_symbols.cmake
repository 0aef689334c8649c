# A file built for AVX2 or AVX-512 (*_avx2.cpp, *_avx512.cpp; src/CMakeLists.txt) must
# define no symbol that the linker could merge with baseline code (a weak, vague-linkage or
# unique symbol outside its own namespace): the baseline code would then run those
# instructions, and a CPU without them would stop on an illegal instruction.
# Run as: cmake -DNM=nm -DLIBRARY=libaster_mechanics.a -DSOURCE=plane_element_avx2.cpp
#               -DNAMESPACE=aster::mechanics::avx2 -P simd_symbols.cmake
execute_process(COMMAND ${NM} -A -C --defined-only ${LIBRARY} OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NM} failed on ${LIBRARY}")
endif()
string(REPLACE "\n" ";" lines "${listing}")
string(REPLACE "." "\\." source_pattern "${SOURCE}")
set(found FALSE)
set(leaks "")
foreach(line IN LISTS lines)
  if(NOT line MATCHES "${source_pattern}\\.o:")
    continue()
  endif()
  set(found TRUE)
  if(line MATCHES ":[0-9a-f]+ [WVuvw] (.*)$")
    set(symbol "${CMAKE_MATCH_1}")
    string(FIND "${symbol}" "${NAMESPACE}::" at)  # anywhere: a template's name follows its type
    if(at EQUAL -1 AND NOT symbol STREQUAL "DW.ref.__gxx_personality_v0")
      string(APPEND leaks "  ${symbol}\n")
    endif()
  endif()
endforeach()
if(NOT found)
  message(FATAL_ERROR "no ${SOURCE} object in ${LIBRARY}")
endif()
if(leaks)
  message(FATAL_ERROR "the SIMD build of ${SOURCE} defines shared symbols "
                      "(inline them with flatten or move them out of line):\n${leaks}")
endif()
message(STATUS "${SOURCE}: no shared symbols")
