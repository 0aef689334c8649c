# A kernel module is every .cpp of src/<name>/: adding a file needs no CMake edit.
# A module without sources yet is an INTERFACE library, so dependents still link.
function(aster_module name)
  cmake_parse_arguments(M "" "" "DEPS" ${ARGN})
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/${name}/*.cpp ${CMAKE_SOURCE_DIR}/src/${name}/*/*.cpp)
  if(srcs)
    add_library(aster_${name} STATIC ${srcs})
    target_include_directories(aster_${name} PUBLIC ${CMAKE_SOURCE_DIR}/src)
    target_link_libraries(aster_${name} PUBLIC ${M_DEPS})
  else()
    add_library(aster_${name} INTERFACE)
    target_include_directories(aster_${name} INTERFACE ${CMAKE_SOURCE_DIR}/src)
    target_link_libraries(aster_${name} INTERFACE ${M_DEPS})
  endif()
endfunction()

# One gtest executable per tests/<name>/ folder, each test registered with ctest.
function(aster_test_folder name)
  cmake_parse_arguments(T "" "" "DEPS" ${ARGN})
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${name}/*.cpp)
  if(srcs)
    add_executable(test_${name} ${srcs})
    target_link_libraries(test_${name} PRIVATE ${T_DEPS} GTest::gtest GTest::gtest_main)
    target_compile_definitions(test_${name} PRIVATE
      ASTER_SOURCE_DIR="${CMAKE_SOURCE_DIR}"
      ASTER_BINARY_DIR="${CMAKE_BINARY_DIR}")
    gtest_discover_tests(test_${name} WORKING_DIRECTORY ${CMAKE_BINARY_DIR} DISCOVERY_TIMEOUT 60)
  endif()
endfunction()
