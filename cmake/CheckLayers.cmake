# The layers of src/: which folders each folder may include. Run as a test:
#   cmake -DSRC=<src folder> -P CheckLayers.cmake
# Every `#include "folder/..."` (or <folder/...>) of a file in src/<dir>/ must name <dir>
# itself or a folder <dir> is allowed below. Files directly in src/ (main.cpp) sit on top.
# The rules are checked too: a folder that reaches itself through them is a cycle, which
# would let an include run upward.

# folder: the folders it may include. One place; a new folder or dependency is added here.
set(ASTER_LAYERS
  "core:"
  "expr:core"
  "linalg:core"
  "mesh:core"
  "fem:core mesh linalg"
  "model:core mesh expr mechanics"
  "mechanics:core expr mesh fem"
  "contact:core expr mesh fem"
  "analysis:core expr linalg mesh fem model mechanics contact"
  "post:core mesh fem expr"
  "comm:core"
  "lang:core comm"
  "commands:core expr linalg mesh fem model mechanics contact analysis post lang"
)

cmake_minimum_required(VERSION 3.16)

if(NOT SRC OR NOT IS_DIRECTORY "${SRC}")
  message(FATAL_ERROR "CheckLayers: give the source folder as -DSRC=<path to src>")
endif()
get_filename_component(SRC "${SRC}" ABSOLUTE)

set(folders "")
foreach(rule IN LISTS ASTER_LAYERS)
  string(REPLACE ":" ";" parts "${rule}")
  list(GET parts 0 folder)
  set(allowed "")
  list(LENGTH parts count)
  if(count GREATER 1)
    list(GET parts 1 below)
    string(REPLACE " " ";" allowed "${below}")
  endif()
  list(APPEND folders ${folder})
  set(allowed_${folder} ${allowed})
endforeach()

set(failures "")

# The rules themselves: no folder may reach itself (the closure is built pass by pass).
foreach(folder IN LISTS folders)
  set(reach ${allowed_${folder}})
  set(grew TRUE)
  while(grew)
    set(grew FALSE)
    foreach(f IN LISTS reach)
      if(NOT f IN_LIST folders)
        list(APPEND failures "rule '${folder}' allows '${f}', which has no rule of its own")
        continue()
      endif()
      foreach(g IN LISTS allowed_${f})
        if(NOT g IN_LIST reach)
          list(APPEND reach ${g})
          set(grew TRUE)
        endif()
      endforeach()
    endforeach()
  endwhile()
  if(folder IN_LIST reach)
    list(APPEND failures "the rules make a cycle through '${folder}': it reaches itself through ${reach}")
  endif()
endforeach()

file(GLOB_RECURSE sources RELATIVE "${SRC}" "${SRC}/*.cpp" "${SRC}/*.hpp" "${SRC}/*.h" "${SRC}/*.inc")
list(SORT sources)
if(NOT sources)
  message(FATAL_ERROR "CheckLayers: no source file under ${SRC}")
endif()
set(checked 0)
foreach(file IN LISTS sources)
  if(NOT file MATCHES "^([^/]+)/")
    continue()  # src/main.cpp: the program, on top of every layer
  endif()
  set(folder ${CMAKE_MATCH_1})
  if(NOT folder IN_LIST folders)
    list(APPEND failures "src/${file}: the folder '${folder}' has no rule in cmake/CheckLayers.cmake (ASTER_LAYERS)")
    continue()
  endif()
  file(STRINGS "${SRC}/${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<][A-Za-z_0-9]+/")
  foreach(line IN LISTS includes)
    string(REGEX MATCH "[\"<]([A-Za-z_0-9]+)/[^\">]*" header "${line}")
    set(target ${CMAKE_MATCH_1})
    string(SUBSTRING "${header}" 1 -1 header)
    if(NOT target IN_LIST folders)
      if(line MATCHES "\"")  # <Eigen/...>, <sys/...>: libraries, not layers
        list(APPEND failures "src/${file} includes \"${header}\": '${target}' is not a folder of src/ with a rule")
      endif()
      continue()
    endif()
    math(EXPR checked "${checked} + 1")
    if(target STREQUAL folder OR target IN_LIST allowed_${folder})
      continue()
    endif()
    string(REPLACE ";" " " allowedText "${allowed_${folder}}")
    if(allowedText STREQUAL "")
      set(allowedText "nothing but itself")
    endif()
    list(APPEND failures
         "src/${file} includes \"${header}\": ${folder} may include ${allowedText} (rule '${folder}' in cmake/CheckLayers.cmake)")
  endforeach()
endforeach()

if(failures)
  list(LENGTH failures n)
  string(REPLACE ";" "\n  " text "${failures}")
  message(FATAL_ERROR "${n} breach(es) of the layers of src/:\n  ${text}")
endif()
message(STATUS "CheckLayers: ${checked} includes of folders in ${SRC} follow the layers")
