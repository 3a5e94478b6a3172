# Type stubs of the flexure module (docs/python.md): names and types for editors and checkers.
import os
from typing import Any, Callable, Sequence, Union

import numpy as np
import numpy.typing as npt

from . import cli as cli
from . import design as design
from . import map as map
from . import mechanism as mechanism
from . import prbm as prbm

__version__: str
git_commit: str

Number = Union[int, float]
Quantity = Union[int, float, str]  # a number in SI units, or a string with a unit ('50mm')
Loads = Union[Number, npt.ArrayLike]  # a scalar, or an array: the result has its shape
Path = Union[str, os.PathLike[str]]
# A physical value of flexure.beam: SI number or text with a unit, or an array of SI numbers (the
# beam is then solved at every entry; a list or array is never read as text).
PhysicalValues = Union[Quantity, npt.ArrayLike]
Result = dict[str, Any]

class InvalidInput(ValueError): ...

class NoConvergence(RuntimeError):
    reached: dict[str, Any]
    def __init__(self, message: str, reached: dict[str, Any] | None = ...) -> None: ...

class FlexureWarning(UserWarning): ...

def beam(
    n: Loads | None = ...,
    alpha2: Loads | None = ...,
    mu: Loads | None = ...,
    theta0: Loads | str | None = ...,
    b_over_l: Loads | None = ...,
    *,
    method: str | None = ...,
    tol: float | None = ...,
    shape: int | None = ...,
    boundary: str | None = ...,
    tip_x: PhysicalValues | None = ...,
    tip_y: PhysicalValues | None = ...,
    tip_angle: Quantity | None = ...,
    follower: float | None = ...,
    elements: int | None = ...,
    increments: int | None = ...,
    chain_variant: str | None = ...,
    integrator: str | None = ...,
    chain: Path | None = ...,
    constants: str | None = ...,
    slenderness: float | None = ...,
    length: PhysicalValues | None = ...,
    E: PhysicalValues | None = ...,
    I: PhysicalValues | None = ...,
    width: PhysicalValues | None = ...,
    thickness: PhysicalValues | None = ...,
    Fx: PhysicalValues | None = ...,
    Fy: PhysicalValues | None = ...,
    M: PhysicalValues | None = ...,
    yield_strength: PhysicalValues | None = ...,
    stable: bool = ...,
    stability: str | None = ...,
    material: str | None = ...,
    cycle: str | None = ...,
    surface_finish: str | None = ...,
    reliability: float | None = ...,
    Kf: float | None = ...,
    fatigue_factor: float | None = ...,
    ultimate_strength: Quantity | None = ...,
    endurance_limit: Quantity | None = ...,
    threads: int | None = ...,
    plate: str | None = ...,
    nu: float | None = ...,
    qx: PhysicalValues | None = ...,
    qy: PhysicalValues | None = ...,
    q_follower: PhysicalValues | None = ...,
    density: PhysicalValues | None = ...,
    g: PhysicalValues | None = ...,
    extensible: bool = ...,
    shear_coefficient: float | None = ...,
    curvature: PhysicalValues | None = ...,
    width_tip: PhysicalValues | None = ...,
    thickness_tip: PhysicalValues | None = ...,
) -> Result: ...
def materials(name: str | None = ...) -> dict[str, Any]: ...
def path(
    *,
    out: Path,
    n: float | None = ...,
    alpha2: float | None = ...,
    mu: float | None = ...,
    follower: float | None = ...,
    boundary: str | None = ...,
    tip_x: Quantity | None = ...,
    tip_y: Quantity | None = ...,
    tip_angle: Quantity | None = ...,
    method: str | None = ...,
    elements: int | None = ...,
    increments: int | None = ...,
    chain: Path | None = ...,
    length: Quantity | None = ...,
    E: Quantity | None = ...,
    I: Quantity | None = ...,
    width: Quantity | None = ...,
    thickness: Quantity | None = ...,
    Fx: Quantity | None = ...,
    Fy: Quantity | None = ...,
    M: Quantity | None = ...,
    max_step: float | None = ...,
    min_points: int | None = ...,
    branch: int | None = ...,
    branch_side: str | None = ...,
    control: str | None = ...,
    shapes: int | None = ...,
    stability: str | None = ...,
    one_way: bool = ...,
    material: str | None = ...,
    plate: str | None = ...,
    nu: float | None = ...,
    qx: Quantity | None = ...,
    qy: Quantity | None = ...,
    q_follower: Quantity | None = ...,
    density: Quantity | None = ...,
    g: Quantity | None = ...,
    extensible: bool = ...,
    shear_coefficient: float | None = ...,
    curvature: Quantity | None = ...,
    width_tip: Quantity | None = ...,
    thickness_tip: Quantity | None = ...,
) -> Result: ...
def sweep(
    *,
    out: Path,
    alpha2: Number | str | None = ...,
    theta0: Number | str | None = ...,
    b_over_l: Number | str | None = ...,
    n: Number | str | None = ...,
    mu: Number | str | None = ...,
    method: str | None = ...,
    threads: int | None = ...,
    compress: bool = ...,
    stability: str | None = ...,
    boundary: str | None = ...,
    tip_x: Quantity | None = ...,
    tip_y: Quantity | None = ...,
    tip_angle: Quantity | None = ...,
    length: Quantity | None = ...,
    E: Quantity | None = ...,
    I: Quantity | None = ...,
    width: Quantity | None = ...,
    thickness: Quantity | None = ...,
    Fx: Quantity | None = ...,
    Fy: Quantity | None = ...,
    M: Quantity | None = ...,
    material: str | None = ...,
    plate: str | None = ...,
    nu: float | None = ...,
    qx: Quantity | None = ...,
    qy: Quantity | None = ...,
    q_follower: Quantity | None = ...,
    density: Quantity | None = ...,
    g: Quantity | None = ...,
    extensible: bool = ...,
    shear_coefficient: float | None = ...,
    curvature: Quantity | None = ...,
    width_tip: Quantity | None = ...,
    thickness_tip: Quantity | None = ...,
    chain: Path | None = ...,
    shapes: int | None = ...,
    progress: Callable[[int, int], object] | None = ...,
) -> Result: ...
def cfm(
    *,
    config: str | None = ...,
    R: float | None = ...,
    K1: float | None = ...,
    K2: float | None = ...,
    d: float | None = ...,
    subclass: str | None = ...,
    sampling: str | None = ...,
    points: int | None = ...,
    curve: bool = ...,
    list: bool = ...,
    table: bool = ...,
    exact: bool = ...,
    exact_points: int | None = ...,
    exact_max_iterations: int | None = ...,
    exact_rows: str | None = ...,
    progress: Callable[[int, int], object] | None = ...,
) -> Result: ...
def dynamics(
    *,
    mechanism: Path | None = ...,
    omega: str | None = ...,
    out: Path | None = ...,
    stroke_percent: float | None = ...,
    spring_rule: str | None = ...,
    force_of: str | None = ...,
    preload_percent: float | None = ...,
    samples: int | None = ...,
    friction: Sequence[float] | None = ...,
    axial_alpha: float | None = ...,
    zero_slider_mass: bool = ...,
    zero_inertia: bool = ...,
    history: Sequence[float] | None = ...,
    list: bool = ...,
    progress: Callable[[int, int], object] | None = ...,
) -> Result: ...
def bench(
    *,
    out: Path,
    quick: bool = ...,
    problems: str | Sequence[str] | None = ...,
    methods: str | Sequence[str] | None = ...,
    resume: bool = ...,
    stop_after: int | None = ...,
) -> Result: ...
def validate(*, out: Path | None = ...) -> Result: ...
def read(path: Path) -> dict[str, Any]: ...

# The library's own types (python/objects.cpp; docs/python.md "Objects"). Their attributes are
# those of the C++ types of the same names; the stubs name the classes only.
BeamMethod: Any
BeamProblem: Any
BeamSolution: Any
ChainAlgorithmSolver: Any
ChainPose: Any
ChainResult: Any
ChainVariant: Any
EllipticBranch: Any
EllipticResult: Any
EllipticSolver: Any
EndCondition: Any
EndLoad: Any
FlexibleSegment: Any
Integrator: Any
Material: Any
NodeLoad: Any
PhysicalBeamSolution: Any
PhysicalChain: Any
PhysicalResults: Any
Reaction: Any
RigidSegment: Any
Section: Any
SegmentChain: Any
SegmentProperties: Any
Shape: Any
ShootingPath: Any
ShootingResult: Any
ShootingSolver: Any
ShootingStrategy: Any
SolveStatus: Any
Stability: Any
StabilityKind: Any
Termination: Any
TipLoad: Any
TipPose: Any
TipPrescription: Any
WarningKind: Any

def flexural_rigidity(section: Any, material: Any) -> float: ...

# The cheaper models of the ladder (python/ladder_objects.cpp; docs/models.md): solve(problem:
# CantileverCase | EndLoad), ChainedBcmSolver also solve(chain: SegmentChain); Options by keyword.
BcmResult: Any
BcmSolver: Any
CantileverCase: Any
CbcmResult: Any
ChainedBcmSolver: Any
LinearBeamResult: Any
LinearBeamSolver: Any
Prbm3rConstants: Any
Prbm3rResult: Any
Prbm3rSolver: Any

# General planar mechanisms (python/mechanism_objects.cpp; docs/mechanisms.md): build with
# GeneralMechanism(name).body(...).pin(...).flexure(...).input(...), or GeneralMechanism.from_toml.
FlexureModel: Any
FlexureModelReport: Any
FlexureTipLoad: Any
GeneralEquilibrium: Any
GeneralExactOptions: Any
GeneralMechanism: Any
GeneralMechanismPoint: Any
GeneralMechanismResult: Any
GeneralPrbmOptions: Any
InputControl: Any
InputCoordinate: Any
JointKind: Any
PrbmKind: Any

def solve_general_prbm(mechanism: Any, options: Any = ..., *, progress: Any = ...) -> Any: ...
def solve_general_exact(mechanism: Any, options: Any = ..., *, progress: Any = ...) -> Any: ...
def solve_general_mixed(mechanism: Any, options: Any = ..., *, progress: Any = ...) -> Any: ...
def check_general_mechanism(mechanism: Any) -> int: ...
StableSelection: Any
def select_stable_points(mechanism: Any, path: Any, *, progress: Any = ...) -> Any: ...

# The constant-force slider mechanisms (python/catalogue_objects.cpp): MechanismDesign.builtin(name),
# .from_toml(path), .from_toml_text(text); analyze_mechanism(design, options, progress=callable).
AnalysisOptions: Any
MechanismAnalysis: Any
MechanismDesign: Any
StrokeStability: Any

def analyze_mechanism(design: Any, options: Any = ..., *, progress: Any = ...) -> Any: ...

# Their dimensional design (python/design_objects.cpp; docs/design.md): MechanismSpec(force=,
# stroke=, E=, length=, ...) in SI units; design_mechanisms(spec, progress=callable) ->
# MechanismDesignReport (.designs best first, .rejected with .binding); refine_design_exact(spec,
# design, progress=callable).
DesignRanking: Any
DimensionedDesign: Any
FlexureOrientation: Any
MechanismDesignReport: Any
MechanismSpec: Any
SizeObjective: Any
StressRule: Any

def design_mechanisms(spec: Any, *, progress: Any = ...) -> Any: ...
def refine_design_exact(spec: Any, design: Any, *, progress: Any = ...) -> Any: ...

def solve_beam(problem: Any, method: Any = ...) -> Any: ...
def solve_physical_chain(chain: Any, method: Any = ..., tolerance: float = ...,
                         shape_points: int = ...) -> Any: ...
