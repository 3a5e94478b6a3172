# The plot module run by `flexure plot` (cli/plot_command.cpp; docs/cli.md "flexure plot"): pure
# Python (matplotlib, h5py), independent of the compiled module, so it is copied and installed
# whether or not pybind11 is present. Build tree: build/share/flexure/python/flexure_plot (next to
# build/flexure); install: <prefix>/share/flexure/python/flexure_plot (next to <prefix>/bin).
file(GLOB FLEXURE_PLOT_FILES RELATIVE ${PROJECT_SOURCE_DIR}/python/flexure_plot
     CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/python/flexure_plot/*.py)
foreach(file ${FLEXURE_PLOT_FILES})
  configure_file(${PROJECT_SOURCE_DIR}/python/flexure_plot/${file}
                 ${PROJECT_BINARY_DIR}/share/flexure/python/flexure_plot/${file} COPYONLY)
endforeach()
list(TRANSFORM FLEXURE_PLOT_FILES PREPEND ${PROJECT_SOURCE_DIR}/python/flexure_plot/)
install(FILES ${FLEXURE_PLOT_FILES}
        DESTINATION ${CMAKE_INSTALL_DATADIR}/flexure/python/flexure_plot)
