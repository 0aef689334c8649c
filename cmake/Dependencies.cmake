# Every dependency comes from Debian 12's packages (see README.md and .ci/run).
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(Threads REQUIRED)

find_path(SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIB cholmod REQUIRED)
find_library(UMFPACK_LIB umfpack REQUIRED)
find_library(KLU_LIB klu REQUIRED)
find_library(AMD_LIB amd REQUIRED)
find_library(COLAMD_LIB colamd REQUIRED)
find_library(SSCONFIG_LIB suitesparseconfig REQUIRED)
# OpenBLAS (libopenblas-dev), linked explicitly and before SuiteSparse: its dgemm_ then
# comes first in the process, whichever libblas.so.3 Debian's alternatives select for
# CHOLMOD (the reference BLAS is ten times slower on the supernodal factorization).
find_library(OPENBLAS_LIB openblas REQUIRED)
add_library(suitesparse INTERFACE)
target_include_directories(suitesparse INTERFACE ${SUITESPARSE_INCLUDE_DIR})
target_link_libraries(suitesparse INTERFACE "-Wl,--push-state,--no-as-needed" ${OPENBLAS_LIB} "-Wl,--pop-state"
  ${CHOLMOD_LIB} ${UMFPACK_LIB} ${KLU_LIB} ${AMD_LIB} ${COLAMD_LIB} ${SSCONFIG_LIB})

# MUMPS, sequential (libmumps-seq-dev): dmumps_c.h includes the mpi.h of its MPI stand-in.
# Double precision (DMUMPS) for METHODE='MUMPS', single (SMUMPS) for GCPC's PRE_COND='LDLT_SP'.
find_path(MUMPS_INCLUDE_DIR dmumps_c.h REQUIRED)
find_path(MUMPS_SEQ_MPI_INCLUDE_DIR mpi.h PATHS /usr/include/mumps_seq NO_DEFAULT_PATH REQUIRED)
find_library(DMUMPS_SEQ_LIB dmumps_seq REQUIRED)
find_library(SMUMPS_SEQ_LIB smumps_seq REQUIRED)
find_library(MUMPS_COMMON_SEQ_LIB mumps_common_seq REQUIRED)
find_library(MPISEQ_SEQ_LIB mpiseq_seq REQUIRED)
find_library(PORD_SEQ_LIB pord_seq REQUIRED)
add_library(mumps_seq INTERFACE)
target_include_directories(mumps_seq INTERFACE ${MUMPS_INCLUDE_DIR} ${MUMPS_SEQ_MPI_INCLUDE_DIR})
target_link_libraries(mumps_seq INTERFACE ${DMUMPS_SEQ_LIB} ${SMUMPS_SEQ_LIB} ${MUMPS_COMMON_SEQ_LIB} ${MPISEQ_SEQ_LIB} ${PORD_SEQ_LIB})

find_path(LUA_INCLUDE_DIR lua.hpp PATH_SUFFIXES lua5.4 REQUIRED)
find_library(LUA_LIB lua5.4 REQUIRED)
add_library(lua54 INTERFACE)
target_include_directories(lua54 INTERFACE ${LUA_INCLUDE_DIR})
target_link_libraries(lua54 INTERFACE ${LUA_LIB} m dl)

# OUT: the soname of the shared library LIB (what dlopen must be given), DEFAULT when
# objdump does not tell it.
function(aster_soname OUT LIB DEFAULT)
  set(soname ${DEFAULT})
  execute_process(COMMAND ${CMAKE_OBJDUMP} -p ${LIB} OUTPUT_VARIABLE headers ERROR_QUIET)
  if(headers MATCHES "SONAME +([^ \n]+)")
    set(soname ${CMAKE_MATCH_1})
  endif()
  set(${OUT} ${soname} PARENT_SCOPE)
endfunction()

# aster-lite loads libgmsh on first use (src/mesh/io/gmsh_library.cpp), by the
# soname of the library found here: gmshapi has the headers and dlopen only.
# gmshlib links the library, for tests calling gmsh's C++ API themselves.
find_path(GMSH_INCLUDE_DIR gmshc.h)
find_library(GMSH_LIB gmsh)
if(GMSH_INCLUDE_DIR AND GMSH_LIB)
  aster_soname(GMSH_SONAME ${GMSH_LIB} libgmsh.so)
  message(STATUS "gmsh, loaded on first use: ${GMSH_SONAME}")
  add_library(gmshapi INTERFACE)
  target_include_directories(gmshapi INTERFACE ${GMSH_INCLUDE_DIR})
  target_link_libraries(gmshapi INTERFACE ${CMAKE_DL_LIBS})
  add_library(gmshlib INTERFACE)
  target_link_libraries(gmshlib INTERFACE gmshapi ${GMSH_LIB})
endif()

find_path(MED_INCLUDE_DIR med.h)
find_library(MED_LIB medC)
find_path(HDF5_MPI_INCLUDE_DIR hdf5.h PATHS /usr/include/hdf5/openmpi NO_DEFAULT_PATH)
find_path(MPI_C_INCLUDE_DIR mpi.h PATHS /usr/lib/x86_64-linux-gnu/openmpi/include NO_DEFAULT_PATH)
# MED too is loaded on first use (src/mesh/io/med_library.cpp), by its soname: medapi has
# the headers and dlopen only; medfile links the library, for tests calling MED themselves.
if(MED_INCLUDE_DIR AND MED_LIB AND HDF5_MPI_INCLUDE_DIR AND MPI_C_INCLUDE_DIR)
  aster_soname(MED_SONAME ${MED_LIB} libmedC.so)
  message(STATUS "MED, loaded on first use: ${MED_SONAME}")
  add_library(medapi INTERFACE)
  target_include_directories(medapi INTERFACE ${MED_INCLUDE_DIR} ${HDF5_MPI_INCLUDE_DIR} ${MPI_C_INCLUDE_DIR})
  target_link_libraries(medapi INTERFACE ${CMAKE_DL_LIBS})
  add_library(medfile INTERFACE)
  target_link_libraries(medfile INTERFACE medapi ${MED_LIB})
endif()

find_package(GTest)
find_package(benchmark QUIET)
