"""flexure.design: designing constant-force mechanisms (`flexure design ...`, docs/design.md)."""
from . import _command


def cfm(*, config=None, d=None, objective=None, subclass=None, pcf_min=None, orientation=None,
        rule_limits=None, K1=None, K2=None, sampling=None, points=None, starts=None,
        scan_points=None, coarse_stride=None, seed=None, model=None, exact_starts=None,
        out=None, all_subclasses=False, progress=None):
    """Synthesis of R, K1, K2 for an objective under the thesis's constraints: `flexure design cfm`.

    config     'spp', 'lpp', 'psp', 'plp', 'ssp', 'slp', 'sps', 'lps' or 'sss' (config, d and
               objective are required unless subclass is given)
    subclass   a thesis sub-class's own problem instead, e.g. 'lps-b95I'
    model      'prbm' or 'exact': maximise the exact model's Xi' from the PRBM optimum
               (keys percent_constant_force_exact, prbm_optimum, exact_evaluations)
    exact_starts  Halton starts of the exact search (default two per variable)
    out        a path: the convergence history as HDF5 (docs/hdf5-schema.md)
    all_subclasses  True: every thesis sub-class from its own problem (or those of config);
               returns {'subclasses': [...], ...}
    d          design stroke, % of r2 + r3 (0 < d < 100); R stays inside its toggle interval
    objective  'min-xi' (Xi = Phi_max/Phi_min, Table 2.1), 'max-pcf' (Xi', %), 'max-psi' (the
               stiffness parameter Psi) or 'min-dn' (d_N,max, % r_tot); the last two need pcf_min
    pcf_min    constraint Xi' >= pcf_min (%)
    orientation  any of 'I', 'O', 'o' (in-plane, out-of-plane, possibly out-of-plane rules)
    rule_limits  other limits of those rules, e.g. "O:C>=0.99,o:D_equal<=10.4"
    K1, K2     hold K1 = k2/k1 or K2 = k3/k1 at this value
    sampling ('auto' | 'thesis' | 'uniform'), points: the model's stroke sampling
    starts, scan_points, coarse_stride, seed: the optimiser's local runs per region of the
               primary pivot, global scan, coarse sampling (every N-th stroke point; 1: all) and
               seed (runs are reproducible; docs/design.md)
    Returns the dict `flexure design cfm --json` prints: the keys of flexure.cfm at the optimum
    (R, K1, K2, Phi, Psi, Xi, percent_constant_force, ...) and objective, objective_value,
    subclass (the thesis sub-class within 1 %, or None), constraints, evaluations, converged,
    seconds (the synthesis's wall time).
    Raises NoConvergence when no feasible design is found.
    progress   progress(done, total) after each scan point and local run of the PRBM synthesis
               (total: the scan points plus the most local runs; (total, total) at its end) and,
               with model='exact', then after each exact stroke of the search, total the most it
               can take (1 + runs * 301 with the default evaluation limit; a run that stops early
               moves done to its end); Ctrl-C or an exception it raises stops it
               (docs/python.md "Progress and Ctrl-C")

    Example:
      >>> flexure.design.cfm(config="lpp", d=40, objective="min-xi")["R"]   # doctest: +SKIP
      0.8858...
    """
    return _command.run(["design", "cfm"], dict(config=config, d=d, objective=objective,
                                                subclass=subclass, pcf_min=pcf_min,
                                                orientation=orientation, rule_limits=rule_limits,
                                                K1=K1, K2=K2, sampling=sampling, points=points,
                                                starts=starts, scan_points=scan_points,
                                                coarse_stride=coarse_stride, seed=seed,
                                                model=model, exact_starts=exact_starts, out=out,
                                                all_subclasses=all_subclasses),
                        switches=("all_subclasses",), progress=progress)


def _range(keyword, value):
    """'A:B' for a (lower, upper) pair; a single value or a 'A:B' string as it is."""
    if isinstance(value, (list, tuple)):
        if len(value) != 2:
            raise _command.InvalidInput(f"{keyword}={value!r}: give (lower, upper) or one value")
        return ":".join(_command.flag_value(keyword, v) for v in value)
    return value


def mechanism(*, force, stroke, safety_factor, length_range, E=None, width_range=None,
              thickness_range=None, yield_strength=None, in_plane=False, out_of_plane=False,
              pcf_min=None, config=None, rank=None, force_of=None, exact=True, model=None,
              points=None, out=None, stress_rule=None, minimize=None,
              max_width_to_thickness=None, max_width_to_length=None, force_tolerance=None,
              allow_infeasible=False, material=None, fatigue=False, surface_finish=None,
              reliability=None, Kf=None, fatigue_factor=None, ultimate_strength=None,
              endurance_limit=None, plate=None, nu=None, progress=None):
    """Dimensional design from a specification (thesis ch. 8): `flexure design mechanism`.

    force, stroke, E, yield_strength   numbers in SI (N, m, Pa) or strings with units ('25lbf',
                    '4in', '30Msi', '200ksi'); force is of one half unless force_of='whole'
    safety_factor   on the yield strength
    length_range, width_range, thickness_range   (lower, upper) or one value: l_tot of one half,
                    flexure width b, flexure thickness h; width and thickness may be left free
    in_plane / out_of_plane   equal widths (flag I) or equal thicknesses (flags O, o)
    pcf_min         keep sub-classes with Xi' >= pcf_min (%)
    config          a configuration or a list of them ('lpp' or ['lpp', 'lps']); default all nine
    rank            'prbm' (the sub-class's Xi', the thesis's rule) or 'exact'
    exact           False skips the exact model (faster; force_exact etc. are None)
    model           'prbm' or 'exact': also refine the best design against the exact model
                    (key 'refined'; out then writes the refined design)
    out             a path: write the best design as TOML for flexure.mechanism.analyze
                    (with its force_of)
    stress_rule     'computed' (default: every design meets safety_factor by the PRBM and the
                    exact stresses, axial stress and clamp moment included) or 'thesis' (eq. 8.5
                    alone, to reproduce the thesis's examples)
    minimize        'length', 'footprint' or 'mass': each sub-class at its smallest feasible
                    design, ranked smallest first (keys footprint, flexure_volume)
    max_width_to_thickness, max_width_to_length   section bounds (defaults 200 and 1: b/h of
                    every flexure, and its width over l_tot)
    force_tolerance largest difference of the exact mean force from force, in % (default 10)
    allow_infeasible  with model='exact' and out: write the refined design even when it misses
                    the specification (marked NOT FEASIBLE; NoConvergence is still raised)
    material        a name of flexure.materials() (E, S_y, S_ut, S_e'; E is then optional)
    fatigue         True: size for and keep only designs with infinite life at safety_factor
                    (surface_finish, reliability, Kf, fatigue_factor, ultimate_strength,
                    endurance_limit; docs/fatigue.md)
    plate           'off' or 'on': size the strips with E or E/(1 - nu^2) (nu: Poisson's ratio,
                    default the material's; docs/plate-modulus.md)
    progress        progress(done, total) after each sub-class (as flexure.design_mechanisms),
                    then with model='exact' after each exact stroke of the refinement (as
                    flexure.refine_design_exact, a second count from 1); Ctrl-C or an exception
                    it raises stops it (docs/python.md "Progress and Ctrl-C")
    Returns the dict `flexure design mechanism --json` prints: designs (best first; each with
    subclass, r2, r3, segment_lengths, width, thicknesses, required_yield_strength, force_prbm,
    force_exact, percent_constant_force_prbm/_exact, safety_factor_prbm/_exact, ...), rejected
    (with the binding constraint and its shortfall) and screens (thesis Table 8.2).
    Raises NoConvergence (with .reached holding rejected and screens) when no design is feasible.

    Example (thesis example 1):
      >>> r = flexure.design.mechanism(force="25lbf", stroke="4in", E="30Msi", safety_factor=1.2,
      ...         length_range=("12in", "15in"), width_range=("3in", "5in"),
      ...         thickness_range=("0.04in", "0.07in"), config="lpp")   # doctest: +SKIP
      >>> r["designs"][0]["subclass"]                                     # doctest: +SKIP
      'lpp-b'
    """
    return _command.run(
        ["design", "mechanism"],
        dict(force=force, stroke=stroke, E=E, yield_strength=yield_strength,
             safety_factor=safety_factor, length_range=_range("length_range", length_range),
             width_range=_range("width_range", width_range),
             thickness_range=_range("thickness_range", thickness_range), in_plane=in_plane,
             out_of_plane=out_of_plane, pcf_min=pcf_min, config=config, rank=rank,
             force_of=force_of, no_exact=not exact, model=model, points=points, out=out,
             stress_rule=stress_rule, minimize=minimize,
             max_width_to_thickness=max_width_to_thickness,
             max_width_to_length=max_width_to_length, force_tolerance=force_tolerance,
             allow_infeasible=allow_infeasible, material=material, fatigue=fatigue,
             surface_finish=surface_finish, reliability=reliability, Kf=Kf,
             fatigue_factor=fatigue_factor, ultimate_strength=ultimate_strength,
             endurance_limit=endurance_limit, plate=plate, nu=nu),
        switches=("in_plane", "out_of_plane", "no_exact", "allow_infeasible", "fatigue"),
        progress=progress)
