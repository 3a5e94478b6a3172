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
    """Howell's Table 5.1 re-derived over a range of n: `flexure prbm table` (rows as columns)."""
    return _command.run(["prbm", "table"], dict(segment=segment, step=step, tail=tail,
                                                n_min=n_min, n_max=n_max, n_steps=n_steps))


def compare(*, segment=None, n=None, alpha2=None, mu=None, constants=None, range=None):
    """The PRBM tip against the exact one at one load, or over a range: `flexure prbm compare`."""
    return _command.run(["prbm", "compare"], dict(segment=segment, n=n, alpha2=alpha2, mu=mu,
                                                  constants=constants, range=range))
