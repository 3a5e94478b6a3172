"""flexure.prbm: pseudo-rigid-body model constants (`flexure prbm ...`, docs/prbm.md)."""
from . import _command


def derive(*, segment=None, kappa0=None, n=None, step=None, theta_max_K=None, tail=None):
    """Derives the PRBM constants of one segment from the exact solution: `flexure prbm derive`.

    segment      'fixed-pinned' (default), ... (the tool's --segment names)
    kappa0       initial curvature kappa0 l (initially curved beams)
    n            load ratio n of the tip force
    step, theta_max_K, tail: the derivation's settings (docs/prbm.md)
    Returns the dict `flexure prbm derive --json` prints (gamma, K_theta, c_theta, Theta_max, ...).

    Example:
      >>> round(flexure.prbm.derive(n=0.0)["gamma"], 3)             # doctest: +SKIP
      0.852
    """
    return _command.run(["prbm", "derive"], dict(segment=segment, kappa0=kappa0, n=n, step=step,
                                                 theta_max_K=theta_max_K, tail=tail))


def table(*, segment=None, step=None, tail=None, n_min=None, n_max=None, n_steps=None):
    """Howell's Tables 5.1 and 5.2 re-derived from the exact solution: `flexure prbm table`.

    segment  'fixed-pinned' (default: Table 5.1 over n, and the Table 5.2 averages),
             'initially-curved' or 'end-moment'
    step     theta0 sampling step, degrees (default 0.1; 0.5 is ten times faster)
    tail     extra samples approaching the force angle phi (0-60)
    n_min, n_max, n_steps: the range of n averaged for Table 5.2 (default -0.5, 1, 6 intervals)
    Returns the dict `flexure prbm table --json` prints: `rows`, a list of dicts (n, gamma,
    K_theta, c_theta, Theta_max in degrees, ...).

    Example:
      >>> t = flexure.prbm.table(step=0.5)                          # doctest: +SKIP
    """
    return _command.run(["prbm", "table"], dict(segment=segment, step=step, tail=tail,
                                                n_min=n_min, n_max=n_max, n_steps=n_steps))


def compare(*, segment=None, n=None, alpha2=None, mu=None, constants=None, range=None):
    """The PRBM's tip against the exact solution: `flexure prbm compare` (docs/prbm.md).

    segment    'fixed-pinned' (default: a tip force alpha2 = P l^2/EI at load ratio n, -5..10)
               or 'end-moment' (a pure moment mu = M l/EI)
    constants  'table' (Howell's printed constants, default), 'fits' or 'derived'
    range      'START:STOP:COUNT' of alpha2 (or mu): one row per load instead of one load
    Returns the dict `flexure prbm compare --json` prints (PRBM and exact tips, errors, Theta
    against its validity limit).

    Example:
      >>> flexure.prbm.compare(n=0.5, range="0.5:5:4")["points"][0]["exact"]  # doctest: +SKIP
    """
    return _command.run(["prbm", "compare"], dict(segment=segment, n=n, alpha2=alpha2, mu=mu,
                                                  constants=constants, range=range))
