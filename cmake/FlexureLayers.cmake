# Helpers for the layered library targets (docs/architecture.md).
#
# Every library layer is a static library `flexure_<layer>` with an explicit source list (no globs)
# that links only the layers below it. Sources include each other as "flexure/<folder>/<file>.h";
# in the build tree that prefix resolves through ${FLEXURE_BUILD_INCLUDE_DIR}/flexure, whose
# entries are symbolic links to the source folders, and after `cmake --install` through
# <prefix>/include/flexure, which holds the public headers only.

set(FLEXURE_BUILD_INCLUDE_DIR ${PROJECT_BINARY_DIR}/include)
file(MAKE_DIRECTORY ${FLEXURE_BUILD_INCLUDE_DIR}/flexure)
foreach(folder solver elements beam mechanisms io benchmarks)
  if(NOT EXISTS ${FLEXURE_BUILD_INCLUDE_DIR}/flexure/${folder})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${folder} ${FLEXURE_BUILD_INCLUDE_DIR}/flexure/${folder}
         SYMBOLIC)
  endif()
endforeach()
# The umbrella and the module headers (include/flexure/*.h: flexure.h, beam.h, ...).
file(GLOB FLEXURE_MODULE_HEADERS RELATIVE ${PROJECT_SOURCE_DIR}/include/flexure
     ${PROJECT_SOURCE_DIR}/include/flexure/*.h)
foreach(header ${FLEXURE_MODULE_HEADERS})
  if(NOT EXISTS ${FLEXURE_BUILD_INCLUDE_DIR}/flexure/${header})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/include/flexure/${header}
         ${FLEXURE_BUILD_INCLUDE_DIR}/flexure/${header} SYMBOLIC)
  endif()
endforeach()

set(FLEXURE_WARNINGS -Wall -Wextra -Wpedantic)

set(FLEXURE_EMBED_DATA_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed_data.cmake)

# flexure_embed_data(<target> <files...>): compiles each data file (path relative to the repository
# root, e.g. data/weight_table_2_1.csv) into <target> as `flexure::EmbeddedFile
# flexure::data::<file name without extension>()`, through a source file generated in the build
# tree by cmake/embed_data.cmake. A change to the data file regenerates and rebuilds it.
function(flexure_embed_data target)
  foreach(file ${ARGN})
    get_filename_component(name ${file} NAME_WE)
    set(input ${PROJECT_SOURCE_DIR}/${file})
    set(output ${CMAKE_CURRENT_BINARY_DIR}/embedded_data/${name}.cpp)
    add_custom_command(
      OUTPUT ${output}
      COMMAND ${CMAKE_COMMAND} -DINPUT=${input} -DOUTPUT=${output} -DNAME=${name} -DPATH=${file}
              -P ${FLEXURE_EMBED_DATA_SCRIPT}
      DEPENDS ${input} ${FLEXURE_EMBED_DATA_SCRIPT}
      COMMENT "Embedding ${file}"
      VERBATIM)
    target_sources(${target} PRIVATE ${output})
  endforeach()
endfunction()

# flexure_add_layer(<layer> SOURCES <files...> [DATA <data files...>] [PUBLIC_LINK <targets...>]
#                   [PRIVATE_LINK <targets...>])
# Defines flexure_<layer>, exported as flexure::<layer>. DATA files are embedded with
# flexure_embed_data.
function(flexure_add_layer layer)
  cmake_parse_arguments(ARG "" "" "SOURCES;DATA;PUBLIC_LINK;PRIVATE_LINK" ${ARGN})
  set(target flexure_${layer})
  add_library(${target} STATIC ${ARG_SOURCES})
  flexure_embed_data(${target} ${ARG_DATA})
  add_library(flexure::${layer} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${layer} POSITION_INDEPENDENT_CODE ON)
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${FLEXURE_BUILD_INCLUDE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_link_libraries(${target} PUBLIC ${ARG_PUBLIC_LINK} PRIVATE ${ARG_PRIVATE_LINK})
  target_compile_options(${target} PRIVATE ${FLEXURE_WARNINGS})
  if(FLEXURE_SANITIZE)
    # A sanitized library needs the sanitizer runtimes wherever it is linked, also in projects
    # that use the installed package (the examples run by ctest).
    target_link_options(${target} INTERFACE ${FLEXURE_SANITIZER_FLAGS})
  endif()
  set_property(GLOBAL APPEND PROPERTY FLEXURE_LAYER_TARGETS ${target})
endfunction()
