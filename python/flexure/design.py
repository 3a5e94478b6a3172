"""flexure.design: designing constant-force mechanisms (`flexure design ...`, docs/design.md)."""
from . import _command


def cfm(*, config, d, objective, pcf_min=None, orientation=None, rule_limits=None, K1=None,
        K2=None, sampling=None, points=None, starts=None, scan_points=None, coarse_stride=None,
        seed=None):
    """Synthesis of R, K1, K2 for an objective under the thesis's constraints: `flexure design cfm`.

    config     'spp', 'lpp', 'psp', 'plp', 'ssp', 'slp', 'sps', 'lps' or 'sss'
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

    Example:
      >>> flexure.design.cfm(config="lpp", d=40, objective="min-xi")["R"]   # doctest: +SKIP
      0.8858...
    """
    return _command.run(["design", "cfm"], dict(config=config, d=d, objective=objective,
                                                pcf_min=pcf_min, orientation=orientation,
                                                rule_limits=rule_limits, K1=K1, K2=K2,
                                                sampling=sampling, points=points,
                                                starts=starts, scan_points=scan_points,
                                                coarse_stride=coarse_stride, seed=seed))
