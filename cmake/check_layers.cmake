# Fails when a source file includes a header of a layer above its own (docs/architecture.md).
# Run at every build (target `layer_check`) and by ctest. Usage:
#   cmake -DSOURCE_DIR=<repo> -P cmake/check_layers.cmake
#
# Rank of each folder; a file may include "flexure/<folder>/..." only for folders of rank <= its own.
# io sits beside the layers: it may use the mechanisms (its TOML readers build their types), and
# only the studies and the tool may use io.
set(layer_folders
  "solver/common" 0
  "solver" 1
  "elements" 2
  "mechanisms" 3
  "io" 4
  "benchmarks/studies" 5)
# Installed (public) headers must not expose these libraries' types.
set(forbidden_in_public "<CLI/" "<nlohmann/" "<hdf5.h>" "<H5" "<toml++/")

function(rank_of path out)
  set(best -1)
  set(best_len 0)
  list(LENGTH layer_folders n)
  math(EXPR last "${n} - 1")
  foreach(i RANGE 0 ${last} 2)
    list(GET layer_folders ${i} folder)
    math(EXPR j "${i} + 1")
    list(GET layer_folders ${j} rank)
    string(LENGTH "${folder}" len)
    string(FIND "${path}" "${folder}/" pos)
    if(pos EQUAL 0 AND len GREATER best_len)
      set(best ${rank})
      set(best_len ${len})
    endif()
  endforeach()
  set(${out} ${best} PARENT_SCOPE)
endfunction()

set(violations "")
file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR}
  ${SOURCE_DIR}/solver/*.h ${SOURCE_DIR}/solver/*.cpp
  ${SOURCE_DIR}/elements/*.h ${SOURCE_DIR}/elements/*.cpp
  ${SOURCE_DIR}/mechanisms/*.h ${SOURCE_DIR}/mechanisms/*.cpp
  ${SOURCE_DIR}/io/*.h ${SOURCE_DIR}/io/*.cpp
  ${SOURCE_DIR}/benchmarks/studies/*.h ${SOURCE_DIR}/benchmarks/studies/*.cpp)
foreach(source ${sources})
  rank_of(${source} own)
  file(STRINGS ${SOURCE_DIR}/${source} lines REGEX "^#include \"")
  foreach(line ${lines})
    if(line MATCHES "^#include \"flexure/([^\"]+)\"")
      set(included ${CMAKE_MATCH_1})
      if(included STREQUAL "version.h")
        continue()
      endif()
      rank_of(${included} theirs)
      if(theirs GREATER own)
        list(APPEND violations "${source} (layer ${own}) includes flexure/${included} (layer ${theirs})")
      endif()
    elseif(line MATCHES "^#include \"(cli|tests)/")
      list(APPEND violations "${source} includes ${line}: the library cannot use the tool or tests")
    endif()
  endforeach()
endforeach()

if(DEFINED PUBLIC_HEADERS_FILE AND EXISTS ${PUBLIC_HEADERS_FILE})
  file(STRINGS ${PUBLIC_HEADERS_FILE} public_headers)
  foreach(header ${public_headers})
    file(STRINGS ${SOURCE_DIR}/${header} lines REGEX "^#include <")
    foreach(line ${lines})
      foreach(bad ${forbidden_in_public})
        string(FIND "${line}" "${bad}" pos)
        if(pos GREATER_EQUAL 0)
          list(APPEND violations "public header ${header}: ${line}")
        endif()
      endforeach()
    endforeach()
  endforeach()
endif()

if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "layering violations:\n  ${text}")
endif()
list(LENGTH sources count)
message(STATUS "layers: ${count} library files checked, no upward includes")
