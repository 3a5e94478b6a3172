# Fails when a library file includes a header of a folder it may not use (docs/architecture.md).
# Run at every build (target `layer_check`) and by ctest. Usage:
#   cmake -DSOURCE_DIR=<repo> [-DPUBLIC_HEADERS_FILE=<list>] -P cmake/check_layers.cmake
#
# The folders form a graph: each names the folders it may include directly, and a file may include
# its own folder and every folder reachable from it. A file belongs to the longest folder of the
# graph that contains it. Both include styles are read, "flexure/..." and <flexure/...>. Because
# the graph has no cycle (checked below), two folders that include each other are a violation:
# no separate cycle finder is needed (scripts/include_graph.py prints cycles for people).
#
# The solver's packages are ranked: the models and the closed forms (ode, elliptic, chain_model)
# below the methods built on them (shooting and chain on chain_model; inverse on elliptic). The
# beam layer (the user-facing beam API: beam problems, the method choice) sits on the elements,
# below the mechanisms (a flexure of a mechanism may use the beam's model ladder and its error
# map), and links no file format.
# The mechanisms' sub-folders are ranked too: the tables compiled in (data) below the constant-force
# configurations and their PRBM (cfm), below the assembled mechanisms and their exact model, below
# dynamics, design and the general mechanisms, which nothing else in the layer includes. io is split:
# its platform (io/platform: atomic HDF5 files, provenance, output paths, temporary-file cleanup,
# MPI ranks and work division) needs only solver/common and sits below the models; the formats
# (the rest of io/: TOML readers, domain writers, drawings, the beam-sweep engine) sit above them.
cmake_minimum_required(VERSION 3.22)  # IN_LIST, list(POP_FRONT)
set(layer_graph
  "solver/common:"
  "solver/ode:solver/common"
  "solver/elliptic:solver/common"
  "solver/chain_model:solver/common"
  "solver/shooting:solver/chain_model"
  "solver/chain:solver/chain_model"
  "solver/inverse:solver/elliptic"
  "elements:solver/shooting,solver/chain,solver/inverse,solver/ode"
  "beam:elements"
  "mechanisms/data:solver/common"
  "mechanisms/cfm:elements,mechanisms/data"
  "mechanisms:elements,beam,mechanisms/cfm"
  "mechanisms/dynamics:mechanisms"
  "mechanisms/design:mechanisms"
  "mechanisms/general:mechanisms"
  "io/platform:solver/common"
  "io:mechanisms/dynamics,mechanisms/design,mechanisms/general,io/platform"
  "benchmarks/studies:io,beam")
# Headers any file may include: generated, no dependencies.
set(allowed_everywhere "version.h")
# Installed (public) headers must not expose these libraries' types.
set(forbidden_in_public "<CLI/" "<nlohmann/" "<hdf5.h>" "<H5" "<toml++/")

# The graph: node list and each node's direct successors.
set(nodes "")
foreach(entry ${layer_graph})
  string(FIND "${entry}" ":" colon)
  string(SUBSTRING "${entry}" 0 ${colon} node)
  math(EXPR after "${colon} + 1")
  string(SUBSTRING "${entry}" ${after} -1 below)
  string(REPLACE "," ";" below "${below}")
  list(APPEND nodes ${node})
  set(direct_${node} ${below})
endforeach()
foreach(node ${nodes})
  foreach(below ${direct_${node}})
    if(NOT below IN_LIST nodes)
      message(FATAL_ERROR "layer graph: ${node} lists ${below}, which is not a node")
    endif()
  endforeach()
endforeach()

# reachable_<node>: every folder below `node` (its transitive successors). A node reaching itself
# is a cycle in the graph, a mistake in the list above.
foreach(node ${nodes})
  set(seen "")
  set(pending ${direct_${node}})
  while(pending)
    list(POP_FRONT pending next)
    if(next STREQUAL node)
      message(FATAL_ERROR "layer graph: ${node} reaches itself; the graph must have no cycle")
    endif()
    if(next IN_LIST seen)
      continue()
    endif()
    list(APPEND seen ${next})
    list(APPEND pending ${direct_${next}})
  endwhile()
  set(reachable_${node} ${seen})
endforeach()

# The node of a path relative to the source root ("" when none): the longest node that is a
# prefix of it.
function(node_of path out)
  set(best "")
  set(best_len 0)
  foreach(node ${nodes})
    string(LENGTH "${node}" len)
    string(FIND "${path}" "${node}/" pos)
    if(pos EQUAL 0 AND len GREATER best_len)
      set(best ${node})
      set(best_len ${len})
    endif()
  endforeach()
  set(${out} "${best}" PARENT_SCOPE)
endfunction()

set(violations "")
set(include_line "^[ \t]*#[ \t]*include[ \t]*[<\"]")
file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR}
  ${SOURCE_DIR}/solver/*.h ${SOURCE_DIR}/solver/*.cpp
  ${SOURCE_DIR}/elements/*.h ${SOURCE_DIR}/elements/*.cpp
  ${SOURCE_DIR}/beam/*.h ${SOURCE_DIR}/beam/*.cpp
  ${SOURCE_DIR}/mechanisms/*.h ${SOURCE_DIR}/mechanisms/*.cpp
  ${SOURCE_DIR}/io/*.h ${SOURCE_DIR}/io/*.cpp
  ${SOURCE_DIR}/benchmarks/studies/*.h ${SOURCE_DIR}/benchmarks/studies/*.cpp)
foreach(source ${sources})
  node_of(${source} own)
  if(own STREQUAL "")
    list(APPEND violations "${source}: in no folder of the layer graph (cmake/check_layers.cmake)")
    continue()
  endif()
  file(STRINGS ${SOURCE_DIR}/${source} lines REGEX "${include_line}")
  foreach(line ${lines})
    if(line MATCHES "${include_line}flexure/([^\">]+)[\">]")
      set(included ${CMAKE_MATCH_1})
      if(included IN_LIST allowed_everywhere)
        continue()
      endif()
      node_of(${included} theirs)
      if(theirs STREQUAL "")
        list(APPEND violations
             "${source}: includes flexure/${included}, which is in no library folder")
      elseif(NOT theirs STREQUAL own AND NOT theirs IN_LIST reachable_${own})
        list(APPEND violations
             "${source}: includes flexure/${included} (${theirs}), which ${own} may not use")
      endif()
    elseif(line MATCHES "${include_line}(cli|tests)/")
      list(APPEND violations "${source}: ${line}: the library cannot use the tool or tests")
    endif()
  endforeach()
endforeach()

# The public headers (the list of cmake/FlexurePublicHeaders.cmake, as the build writes it): none
# exposes a tool library's types, and each includes only public headers, so the installed set is
# closed (an internal header reached from a public one would be missing from the install).
if(DEFINED PUBLIC_HEADERS_FILE AND EXISTS ${PUBLIC_HEADERS_FILE})
  file(STRINGS ${PUBLIC_HEADERS_FILE} public_headers)
  foreach(header ${public_headers})
    file(STRINGS ${SOURCE_DIR}/${header} lines REGEX "${include_line}")
    foreach(line ${lines})
      foreach(bad ${forbidden_in_public})
        string(FIND "${line}" "${bad}" pos)
        if(pos GREATER_EQUAL 0)
          list(APPEND violations "public header ${header}: ${line}")
        endif()
      endforeach()
      if(line MATCHES "${include_line}flexure/([^\">]+)[\">]")
        set(included ${CMAKE_MATCH_1})
        if(included IN_LIST allowed_everywhere)
          continue()
        endif()
        if(NOT included MATCHES "/")
          set(included include/flexure/${included})  # a module header
        endif()
        if(NOT included IN_LIST public_headers)
          list(APPEND violations "public header ${header}: includes ${included}, which is not \
public (not installed: cmake/FlexurePublicHeaders.cmake)")
        endif()
      endif()
    endforeach()
  endforeach()
endif()

if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "layering violations:\n  ${text}")
endif()
list(LENGTH sources count)
message(STATUS "layers: ${count} library files checked, no include outside the layer graph")
