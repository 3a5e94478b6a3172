"""flexure: exact large-deflection beams and compliant mechanisms, from Python.

The library's objects under their C++ names, constructible with keyword arguments: end loads,
sections and materials, segments and chains, the solvers with their Options, results with
attributes and a Termination (docs/python.md "Objects"):

    >>> import flexure
    >>> flexure.EllipticSolver().solve(flexure.EndLoad.howell(0.0, 2.0, 0.0)).tip.theta0
    ...                                                         # doctest: +SKIP

The command functions (flexure.cli: each runs the `flexure` command of the same name in this
process and returns the dict its --json output holds) stay under their first names too, for
existing scripts. Invalid input raises InvalidInput (a ValueError) with the tool's message; no
converged solution raises NoConvergence (a RuntimeError) with `.reached`; warnings are
FlexureWarning warnings. docs/python.md has the whole API.

    >>> flexure.beam(alpha2=2.0)["theta0"]                      # doctest: +ELLIPSIS
    0.6...
"""
from . import _core, cli, design, map, mechanism, prbm
from ._beam import beam
from ._command import FlexureWarning, InvalidInput, NoConvergence
from ._read import read
# The command functions (flexure.cli), also under their first names for existing scripts.
from .cli import bench, cfm, dynamics, materials, path, sweep, validate
# The library's own types (python/objects.cpp; docs/python.md "Objects"): under their C++ names,
# constructible with keyword arguments; results carry termination, message and warnings.
from ._core import flexural_rigidity
from ._core import (BeamMethod, BeamProblem, BeamSolution, ChainAlgorithmSolver, ChainPose,
                    ChainResult, ChainVariant, EllipticBranch, EllipticResult, EllipticSolver,
                    EndCondition, EndLoad, FlexibleSegment, Integrator, Material, NodeLoad,
                    PhysicalBeamSolution, PhysicalChain, PhysicalResults, Reaction, RigidSegment,
                    Section, SegmentChain, SegmentProperties, Shape, ShootingPath, ShootingResult,
                    ShootingSolver, ShootingStrategy, SolveStatus, Stability, StabilityKind,
                    Termination, TipLoad, TipPose, TipPrescription, WarningKind, solve_beam,
                    solve_physical_chain)
# The cheaper models of the ladder (python/ladder_objects.cpp; docs/models.md).
from ._core import (BcmResult, BcmSolver, CantileverCase, CbcmResult, ChainedBcmSolver,
                    LinearBeamResult, LinearBeamSolver, Prbm3rConstants, Prbm3rResult,
                    Prbm3rSolver)
# General planar mechanisms (python/mechanism_objects.cpp; docs/mechanisms.md "General
# mechanisms"): the description, its two models' options and results, the solves.
from ._core import (FlexureModel, FlexureModelReport, FlexurePointResult, FlexureTipLoad,
                    GeneralEquilibrium, GeneralExactOptions, GeneralMechanism,
                    GeneralMechanismPoint, GeneralMechanismResult, GeneralPrbmOptions,
                    InputControl, InputCoordinate, JointKind, JointPointResult, PointLoad,
                    PrbmKind, StableSelection, check_general_mechanism, select_stable_points,
                    solve_general_exact, solve_general_mixed,
                    solve_general_prbm)
# The constant-force slider mechanisms (python/catalogue_objects.cpp; docs/mechanisms.md).
from ._core import (AnalysisOptions, MechanismAnalysis, MechanismDesign, StrokeStability,
                    analyze_mechanism)
# Their dimensional design (python/design_objects.cpp; docs/design.md "Dimensional design").
from ._core import (DesignRanking, DimensionedDesign, FlexureOrientation, MechanismDesignReport,
                    MechanismSpec, SizeObjective, StressRule, design_mechanisms,
                    refine_design_exact)

__version__ = _core.version
git_commit = _core.git_commit

__all__ = ["cli", "beam", "path", "sweep", "cfm", "dynamics", "bench", "validate", "read", "prbm",
           "mechanism", "design", "map", "materials", "InvalidInput", "NoConvergence",
           "FlexureWarning",
           "BeamMethod", "BeamProblem", "BeamSolution", "ChainAlgorithmSolver", "ChainPose",
           "ChainResult", "ChainVariant", "EllipticBranch", "EllipticResult", "EllipticSolver",
           "EndCondition", "EndLoad", "FlexibleSegment", "Integrator", "Material", "NodeLoad",
           "PhysicalBeamSolution", "PhysicalChain", "PhysicalResults", "Reaction", "RigidSegment",
           "Section", "SegmentChain", "SegmentProperties", "Shape", "ShootingPath",
           "ShootingResult", "ShootingSolver", "ShootingStrategy", "SolveStatus", "Stability",
           "StabilityKind", "Termination", "TipLoad", "TipPose", "TipPrescription", "WarningKind",
           "solve_beam", "solve_physical_chain",
           "BcmResult", "BcmSolver", "CantileverCase", "CbcmResult", "ChainedBcmSolver",
           "LinearBeamResult", "LinearBeamSolver", "Prbm3rConstants", "Prbm3rResult",
           "Prbm3rSolver",
           "FlexureModel", "FlexureModelReport", "FlexurePointResult", "FlexureTipLoad",
           "JointPointResult", "PointLoad", "GeneralEquilibrium",
           "GeneralExactOptions", "GeneralMechanism", "GeneralMechanismPoint",
           "GeneralMechanismResult", "GeneralPrbmOptions", "InputControl", "InputCoordinate",
           "JointKind", "PrbmKind", "StableSelection", "check_general_mechanism",
           "select_stable_points", "solve_general_exact", "solve_general_mixed",
           "solve_general_prbm",
           "AnalysisOptions", "MechanismAnalysis", "MechanismDesign", "StrokeStability",
           "analyze_mechanism",
           "DesignRanking", "DimensionedDesign", "FlexureOrientation", "MechanismDesignReport",
           "MechanismSpec", "SizeObjective", "StressRule", "design_mechanisms",
           "refine_design_exact", "flexural_rigidity"]
