# `cmake --install build --prefix P` installs the layer libraries, the public headers (the explicit
# list of cmake/FlexurePublicHeaders.cmake; internal headers stay out) and a CMake package, so that
# an outside project can do
#   find_package(flexure REQUIRED)
#   target_link_libraries(app PRIVATE flexure::flexure)
include(CMakePackageConfigHelpers)
include(${CMAKE_CURRENT_LIST_DIR}/FlexurePublicHeaders.cmake)

foreach(header ${FLEXURE_PUBLIC_HEADERS})
  get_filename_component(dir ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/${header}
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/flexure/${dir})
endforeach()
# The umbrella and the module headers install beside the generated version.h.
list(TRANSFORM FLEXURE_MODULE_HEADERS PREPEND ${PROJECT_SOURCE_DIR}/ OUTPUT_VARIABLE module_paths)
install(FILES ${module_paths} ${PROJECT_BINARY_DIR}/include/flexure/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/flexure)
# For the layer check and tests/consumers/headers: every installed header but the generated
# version.h, the module headers first (relative to the source root).
string(REPLACE ";" "\n" FLEXURE_PUBLIC_HEADER_LINES
               "${FLEXURE_MODULE_HEADERS};${FLEXURE_PUBLIC_HEADERS}")
file(WRITE ${PROJECT_BINARY_DIR}/public_headers.txt "${FLEXURE_PUBLIC_HEADER_LINES}\n")

# Two export sets (issue 28): the beam component (core, solvers, elements, beam: Eigen, GSL,
# SUNDIALS and fmt, no file format) and the rest (mechanisms, io, studies, the umbrella, HDF5,
# toml++, NLopt). `find_package(flexure COMPONENTS beam)` loads only the first
# (cmake/flexureConfig.cmake.in), so a beam-only consumer finds and links no HDF5 and no toml++.
set(FLEXURE_BEAM_COMPONENT_TARGETS flexure_core flexure_solvers flexure_elements flexure_beam)
get_property(FLEXURE_LAYER_TARGETS GLOBAL PROPERTY FLEXURE_LAYER_TARGETS)
set(FLEXURE_FULL_TARGETS ${FLEXURE_LAYER_TARGETS})
list(REMOVE_ITEM FLEXURE_FULL_TARGETS ${FLEXURE_BEAM_COMPONENT_TARGETS})
install(TARGETS ${FLEXURE_BEAM_COMPONENT_TARGETS}
        EXPORT flexureBeamTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS ${FLEXURE_FULL_TARGETS} flexure_library flexure_hdf5
        EXPORT flexureTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS flexure RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT flexureBeamTargets
        NAMESPACE flexure::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/flexure)
install(EXPORT flexureTargets
        NAMESPACE flexure::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/flexure)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/flexureConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/flexureConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/flexure)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/flexureConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/flexureConfig.cmake
              ${PROJECT_BINARY_DIR}/flexureConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/flexure)

# The layering check runs with every build: an upward include fails the build
# (cmake/check_layers.cmake); ctest runs it too.
add_custom_target(layer_check ALL
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
          -DPUBLIC_HEADERS_FILE=${PROJECT_BINARY_DIR}/public_headers.txt
          -P ${PROJECT_SOURCE_DIR}/cmake/check_layers.cmake
  COMMENT "Checking that no layer includes a layer above it"
  VERBATIM)
add_dependencies(flexure layer_check)
