# flexure's public C++ API: the headers `cmake --install` installs, and no others (internal
# headers stay in the build tree). docs/architecture.md, "Public API", says what each offers.
#
# A public header may include only public headers: the layer check (cmake/check_layers.cmake,
# every build and ctest LayerCheck.*) fails naming the header when one includes a header missing
# from these lists, and Install.PublicHeadersSelfContained compiles each installed header alone
# against the install prefix. To make a header public, add it here and to its module header.

# The umbrella and the module headers (include/flexure/): flexure.h includes the five.
set(FLEXURE_MODULE_HEADERS
  include/flexure/flexure.h
  include/flexure/beam.h
  include/flexure/prbm.h
  include/flexure/mechanisms.h
  include/flexure/design.h
  include/flexure/studies.h)

# The headers the module headers reach, by module.
set(FLEXURE_PUBLIC_HEADERS
  # beam.h: core, the solvers, the beam layer.
  solver/common/end_load.h
  solver/common/section.h
  solver/common/status.h
  solver/chain/chain_algorithm_solver.h
  solver/chain_model/segment_chain.h
  solver/elliptic/elliptic_solver.h
  solver/inverse/tip_target.h
  solver/shooting/rigid_contact.h
  solver/shooting/shooting_solver.h
  beam/beam_problem.h
  beam/physical_beam.h
  # prbm.h: pseudo-rigid-body models, the model ladder's beam models.
  beam/prbm_comparison.h
  elements/ladder_models.h
  elements/prbm_element.h
  # mechanisms.h: designs, analysis, constant-force mechanisms, dynamics, general mechanisms.
  mechanisms/builtin_designs.h
  mechanisms/materials_fatigue.h
  mechanisms/mechanism.h
  mechanisms/mechanism_analysis.h
  mechanisms/cfm/cfm_model.h
  mechanisms/dynamics/dynamics.h
  mechanisms/general/general_analysis.h
  mechanisms/general/general_mechanism.h
  # design.h: constant-force and mechanism design.
  mechanisms/design/cfm_synthesis.h
  mechanisms/design/mechanism_synthesis.h
  # studies.h: files (TOML) and drawings.
  io/mechanism_drawing.h
  io/toml_files.h)
