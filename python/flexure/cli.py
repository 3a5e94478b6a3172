"""The command functions: each runs the `flexure` command of the same name in this process.

Each takes that command's flags as keyword arguments (snake_case: --b-over-l -> b_over_l,
--theta-max-K -> theta_max_K; switches as True) and returns the dict its --json output holds,
with the same keys, arrays of numbers as numpy arrays. Invalid input raises InvalidInput (a
ValueError) with the tool's message; no converged solution raises NoConvergence (a RuntimeError)
with `.reached`; the tool's warnings are FlexureWarning warnings (docs/python.md "Command
functions").

The library's objects (flexure.EllipticSolver, flexure.SegmentChain, flexure.MechanismSpec, ...)
are the package's top level; these functions are kept here, and under their old top-level names
(flexure.beam, flexure.cfm, flexure.design.cfm, ...: the same function objects), for scripts
written against the command line.

    >>> import flexure.cli
    >>> flexure.cli.beam(alpha2=2.0)["theta0"]                  # doctest: +ELLIPSIS
    0.6...
"""
from . import design, map, mechanism, prbm  # noqa: A004 - `map`: the tool's command name
from ._beam import beam
from ._command import InvalidInput, run as _run
from ._read import read

__all__ = ["beam", "path", "sweep", "cfm", "dynamics", "bench", "validate", "materials", "read",
           "prbm", "mechanism", "design", "map"]


def _one_value_each(command, options):
    """Refuses a list, tuple or array for a keyword of `command` (one value each): the tool
    would read it as one text. Many loads: flexure.beam with arrays, or a sweep's ranges."""
    for key, value in options.items():
        if isinstance(value, (list, tuple)) or (hasattr(value, "ndim") and value.ndim > 0):
            raise InvalidInput(
                f"{key}={value!r:.60}: flexure.{command} takes one value per keyword; for many "
                f"values call flexure.beam with arrays, or flexure.sweep with a range "
                f"'START:STOP:COUNT' (units allowed: '0N:5N:51')")


def materials(name=None):
    """The material library (Howell Appendix C; docs/materials.md): `flexure materials`.

    name: one material (an id or designation, e.g. 'steel-1095-hr' or '1095 HR'); None: all.
    Returns the dict `flexure materials --json` prints: `materials`, a list of dicts (id, E, nu,
    yield_strength, ultimate_strength, endurance_limit, density, source, notes; SI, None where
    the source has no value). An unknown name raises InvalidInput naming the closest ids.

    Example:
      >>> flexure.materials("1095 HR")["materials"][0]["ultimate_strength"]
      830000000.0
    """
    return _run(["materials"], {}, positional=[] if name is None else [name])


def path(*, out, n=None, alpha2=None, mu=None, follower=None, boundary=None, tip_x=None,
         tip_y=None, tip_angle=None, method=None, elements=None, increments=None, chain=None,
         length=None, E=None, I=None, width=None, thickness=None, Fx=None, Fy=None, M=None,
         max_step=None, min_points=None, branch=None, branch_side=None, control=None,
         shapes=None, stability=None, one_way=False, material=None, plate=None, nu=None,
         qx=None, qy=None, q_follower=None, density=None, g=None, extensible=False,
         shear_coefficient=None, curvature=None, width_tip=None,
         thickness_tip=None):  # noqa: E741 - the tool's flag --I
    """The equilibrium path from the unloaded beam to a load, step by step: `flexure path`.

    The loads and end conditions of flexure.beam (n, alpha2, mu, follower, boundary, tip_x,
    tip_y, tip_angle, chain), or a physical beam (length, E, I or width and thickness, Fx, Fy, M;
    any boundary); method 'shooting' (continuation, the default) or 'chain' (load increments:
    elements, increments), or with control the ladder's 'cbcm' (elements, default 20) or 'bcm'
    (docs/models.md); out: the HDF5 file the path is written to (required). Continuation:
    max_step, min_points, branch (follow the other branch at the N-th bifurcation; branch_side
    'positive' or 'negative'), control ('tip-x', 'tip-y', 'tip-angle': move that coordinate to
    its tip_... value as the path parameter), shapes (K shape points at every path point).
    stability: 'on' (default) or 'off', the verdict of every point under the path's control.
    one_way=True (with control): move the coordinate one way past a fold, as an experiment does.
    The physical beam takes material, plate and nu, the distributed loads qx, qy, q_follower,
    density and g, extensible=True (with nu, shear_coefficient), curvature (1/m) and a taper
    (width_tip, thickness_tip) as flexure.beam does. Under control the force-displacement curve
    is in the file: flexure.read(out)["tip_y"] against ["tip_Fy"] (or x, theta), and its zeros and
    extrema in the returned `force_points`.
    Returns the dict `flexure path --json` prints: the counts, the located `bifurcations` and
    `limit_point_list` (lists of dicts with load_factor, index, index_after, tip and reactions),
    and per point `stability` (list of str), `stability_index` and `stability_margin` (arrays,
    NaN where not judged) and `stability_stretches`.

    Example:
      >>> flexure.path(length=1, E=1, I=1, Fx=-30, out="column.h5")["bifurcations"][0]["load_factor"]  # doctest: +SKIP
      0.0822467033...
    """
    options = dict(n=n, alpha2=alpha2, mu=mu, follower=follower, boundary=boundary,
                   tip_x=tip_x, tip_y=tip_y, tip_angle=tip_angle, method=method,
                   elements=elements, increments=increments, chain=chain,
                   length=length, E=E, I=I, width=width, thickness=thickness, Fx=Fx,
                   Fy=Fy, M=M, max_step=max_step, min_points=min_points,
                   branch=branch, branch_side=branch_side, control=control,
                   shapes=shapes, stability=stability, out=out,
                   one_way=one_way, material=material, plate=plate, nu=nu, qx=qx,
                   qy=qy, q_follower=q_follower, density=density, g=g,
                   extensible=extensible, shear_coefficient=shear_coefficient,
                   curvature=curvature, width_tip=width_tip,
                   thickness_tip=thickness_tip)
    _one_value_each("path", options)
    return _run(["path"], options, switches={"one_way", "extensible"})


def sweep(*, out, alpha2=None, theta0=None, b_over_l=None, n=None, mu=None, method=None,
          threads=None, compress=False, stability=None, boundary=None, tip_x=None, tip_y=None,
          tip_angle=None, length=None, E=None, I=None, width=None, thickness=None, Fx=None,
          Fy=None, M=None, material=None, plate=None, nu=None, qx=None, qy=None,
          q_follower=None, density=None, g=None, extensible=False, shear_coefficient=None,
          curvature=None, width_tip=None, thickness_tip=None,
          chain=None, shapes=None, progress=None):  # noqa: E741 - the tool's --I
    """A beam sweep written to HDF5: `flexure sweep beam` (docs/hdf5-schema.md).

    alpha2, theta0, b_over_l, n, mu: a value or 'START:STOP:COUNT' (one or two axes); method;
    threads; compress; stability: 'on' (default: a verdict per point in /stability,
    /stability_index, /stability_margin) or 'off'; out: the HDF5 file (required). Returns the summary `--json` prints; read
    the file with flexure.read(out). For arrays in memory use flexure.beam with numpy arrays.
    boundary, tip_x, tip_y, tip_angle: a held end as in flexure.beam. A physical beam (length,
    E, I or width and thickness, and the keywords of flexure.beam) is swept over one or two of
    its tip loads Fx, Fy, M given as 'START:STOP:COUNT' with units ('0N:5N:51'); the file then
    has /axes/Fy (N) and the root attributes units 'SI', length_m, EI_Nm2. chain: a segment
    chain TOML file whose tip load Fx, Fy, M (ranges) is swept. shapes: K shape points at every
    sweep point, stored in /shapes of out with internal forces (and fibre stresses of a physical
    rectangle) and an XDMF sidecar (the summary's 'xdmf'); points x K at most 5e6.
    progress(done, total): called about every 0.1 s with the points solved (total: the grid's),
    and with (total, total) at the end; Ctrl-C or an exception it raises stops the sweep and no
    `out` file is written (docs/python.md "Progress and Ctrl-C").

    Example:
      >>> flexure.sweep(alpha2="0:20:1001", n="0:2:3", out="sweep.h5")     # doctest: +SKIP
      >>> flexure.read("sweep.h5")["theta0"].shape                          # doctest: +SKIP
      (1001, 3)
    """
    options = dict(alpha2=alpha2, theta0=theta0, b_over_l=b_over_l, n=n,
                   mu=mu, method=method, out=out, threads=threads,
                   compress=compress, stability=stability,
                   boundary=boundary, tip_x=tip_x, tip_y=tip_y,
                   tip_angle=tip_angle, length=length, E=E, I=I,
                   width=width, thickness=thickness, Fx=Fx, Fy=Fy, M=M,
                   material=material, plate=plate, nu=nu, qx=qx, qy=qy,
                   q_follower=q_follower, density=density, g=g,
                   extensible=extensible,
                   shear_coefficient=shear_coefficient,
                   curvature=curvature, width_tip=width_tip,
                   thickness_tip=thickness_tip, chain=chain, shapes=shapes)
    _one_value_each("sweep", options)
    return _run(["sweep", "beam"], options, switches={"compress", "extensible"},
                progress=progress)


def cfm(*, config=None, R=None, K1=None, K2=None, d=None, subclass=None, sampling=None,
        points=None, curve=False, list=False, table=False, exact=False, exact_points=None,
        exact_max_iterations=None, exact_rows=None,
        progress=None):  # noqa: A002 - the tool's flag --list
    """Nondimensional constant-force mechanism analysis (Weight's thesis): `flexure cfm`.

    config ('1A', '2B', ...), R, K1, K2, d or a thesis subclass ('lpp-b'); sampling, points;
    curve=True adds the force curve; list=True lists the configurations; table=True reproduces
    the thesis tables; exact=True also evaluates the exact model (exact_points,
    exact_max_iterations, exact_rows). R = r3/r2, K1 = k2/k1, K2 = k3/k1 (nondimensional), d the
    stroke in % of r2 + r3. Returns the dict `flexure cfm --json` prints (Phi, Psi, Xi, percent
    constant force, ...). progress(done, total): called after each exact stroke point of
    table=True, exact=True (total: rows times exact_points); Ctrl-C or an exception it raises
    stops the table (docs/python.md "Progress and Ctrl-C").

    Example:
      >>> flexure.cfm(subclass="lpp-b", exact=True)                        # doctest: +SKIP
    """
    return _run(["cfm"], dict(config=config, R=R, K1=K1, K2=K2, d=d, subclass=subclass,
                              sampling=sampling, points=points, curve=curve, list=list,
                              table=table, exact=exact, exact_points=exact_points,
                              exact_max_iterations=exact_max_iterations, exact_rows=exact_rows),
                switches={"curve", "list", "table", "exact"}, progress=progress)


def dynamics(*, mechanism=None, omega=None, out=None, stroke_percent=None, spring_rule=None,
             force_of=None, preload_percent=None, samples=None, friction=None, axial_alpha=None,
             zero_slider_mass=False, zero_inertia=False, history=None, list=False,
             progress=None):  # noqa: A002
    """Inverse dynamics of a modified constant-force slider mechanism: `flexure dynamics`.

    mechanism: a design of the paper's Table 5 ('2B-lplm') or a TOML file with a [dynamics]
    table; omega 'START:STOP:COUNT' (rad/s); stroke_percent, preload_percent, samples,
    friction (C1, C2, C3 in N m), axial_alpha, zero_slider_mass, zero_inertia, history (rad/s),
    spring_rule, force_of ('whole' | 'half'); out: also write HDF5; list=True lists the designs.
    Returns the dict `flexure dynamics --json` prints (forces in N, times in s, omega in rad/s).
    progress(done, total): called after each frequency (total: omega's COUNT); Ctrl-C or an
    exception it raises stops the study, and no `out` file is written (docs/python.md
    "Progress and Ctrl-C").

    Example:
      >>> flexure.dynamics(mechanism="2B-lplm", omega="5:50:10")           # doctest: +SKIP
    """
    return _run(["dynamics"], dict(mechanism=mechanism, omega=omega, out=out,
                                   stroke_percent=stroke_percent, spring_rule=spring_rule,
                                   force_of=force_of, preload_percent=preload_percent,
                                   samples=samples, friction=friction, axial_alpha=axial_alpha,
                                   zero_slider_mass=zero_slider_mass, zero_inertia=zero_inertia,
                                   history=history, list=list),
                switches={"zero_slider_mass", "zero_inertia", "list"}, progress=progress)


def bench(*, out, quick=False, problems=None, methods=None, resume=False, stop_after=None):
    """Accuracy against time of every method on the standard problems: `flexure bench`
    (docs/benchmarks.md). out: the HDF5 file (required); quick=True for the small set; problems,
    methods: names or lists of names; resume=True continues an interrupted run; stop_after.
    Returns the summary `--json` prints; the results are in the file (flexure.read(out)).

    Example:
      >>> flexure.bench(out="quick.h5", quick=True, methods=["elliptic", "prbm"])   # doctest: +SKIP
    """
    return _run(["bench"], dict(out=out, quick=quick, problems=problems, methods=methods,
                                resume=resume, stop_after=stop_after),
                switches={"quick", "resume"})


def validate(*, out=None):
    """Every reference problem with every method against its reference: `flexure validate`.

    out: the results file (default validation.h5 in the current folder). Returns the dict
    `--json` prints (all_passed, and per check the computed and reference values, the relative
    error and its tolerance); a failed check is reported in it, not raised.

    Example:
      >>> flexure.validate(out="checks.h5")["all_passed"]                    # doctest: +SKIP
      True
    """
    return _run(["validate"], dict(out=out))
