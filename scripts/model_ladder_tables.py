#!/usr/bin/python3
"""The convergence and limit tables of docs/models.md, measured with the flexure module.

Usage (from a build tree; Debian's numpy):
  PYTHONPATH=build/python /usr/bin/python3 scripts/model_ladder_tables.py

Prints Markdown:
  1. the chained BCM's tip position error per length against N on seeded random free-end loads
     (n in [-0.5, 1], alpha2 in [0.5, 5], mu in [-1, 1]; seed 30), the largest over the loads, and
     the order log2(e(N/2)/e(N)) measured between successive N;
  2. the BCM's error (one element) against its transverse deflection |y|/l, free and guided ends
     (n = 0): where it stays within 1 % and 0.1 % of the length;
  3. the PR-3R model (Su's constants and flexure's) and Howell's 1R model against the load alpha2
     (n = 0, mu = 0), and PR-3R against mu alone;
  4. linear theory against alpha2 (n = 0, mu = 0).
Every error is |(a, b) - (a, b)_exact| / l against the elliptic solution.
"""
import math

import numpy as np

import flexure


def exact(**loads):
    return flexure.beam(method="elliptic", **loads)


def error(model, reference):
    return np.hypot(model["a_over_l"] - reference["a_over_l"],
                    model["b_over_l"] - reference["b_over_l"])


def cbcm_convergence():
    rng = np.random.default_rng(30)
    loads = dict(n=rng.uniform(-0.5, 1.0, 40), alpha2=rng.uniform(0.5, 5.0, 40),
                 mu=rng.uniform(-1.0, 1.0, 40))
    ref = exact(**loads)
    print("| N | largest error/l | median error/l | order (largest) | order (median) |")
    print("|---|---|---|---|---|")
    previous = None
    for n in (1, 2, 4, 8, 16, 32, 64):
        method = "bcm" if n == 1 else "cbcm"
        extra = {} if n == 1 else {"elements": n}
        import warnings
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            r = flexure.beam(method=method, **extra, **loads)
        ok = r["converged"] & ref["converged"]
        e = error(r, ref)[ok]
        worst, median = e.max(), np.median(e)
        orders = ("", "")
        if previous is not None:
            orders = (f"{math.log2(previous[0] / worst):.2f}",
                      f"{math.log2(previous[1] / median):.2f}")
        print(f"| {n} | {worst:.2e} | {median:.2e} | {orders[0]} | {orders[1]} |"
              + ("" if ok.all() else f" ({(~ok).sum()} not converged)"))
        previous = (worst, median)


def bcm_against_deflection():
    alpha2 = np.array([0.03, 0.1, 0.2, 0.3, 0.45, 0.6, 0.9, 1.2, 1.8, 2.4])
    print("| end | alpha2 | BCM \\|y\\|/l | BCM error/l | linear error/l |")
    print("|---|---|---|---|---|")
    import warnings
    for boundary in ("free", "guided"):
        a = alpha2 if boundary == "free" else 4 * alpha2
        ref = flexure.beam(alpha2=a, boundary=boundary,
                           method="elliptic" if boundary == "free" else "shooting")
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            b = flexure.beam(alpha2=a, boundary=boundary, method="bcm")
        lin = flexure.beam(alpha2=a, boundary=boundary, method="linear")
        for i in range(len(a)):
            print(f"| {boundary} | {a[i]:g} | {b['max_element_deflection'][i]:.3f} | "
                  f"{error(b, ref)[i]:.2e} | {error(lin, ref)[i]:.2e} |")


def prbm_against_load():
    alpha2 = np.array([0.01, 0.1, 0.5, 1.0, 2.0, 3.0, 5.0, 8.0, 10.0, 15.0])
    ref = exact(alpha2=alpha2)
    print("| alpha2 | theta0 exact | linear | 1R (prbm) | PR-3R su | PR-3R flexure |")
    print("|---|---|---|---|---|---|")
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rows = [flexure.beam(alpha2=alpha2, method="linear"),
                flexure.beam(alpha2=alpha2, method="prbm"),
                flexure.beam(alpha2=alpha2, method="prbm3r"),
                flexure.beam(alpha2=alpha2, method="prbm3r", constants="flexure")]
    errors = [error(r, ref) for r in rows]
    for i in range(len(alpha2)):
        print(f"| {alpha2[i]:g} | {ref['theta0'][i]:.3f} | "
              + " | ".join(f"{e[i]:.1e}" for e in errors) + " |")
    mu = np.array([0.1, 0.5, 1.0, 2.0, 3.0, 4.0])
    ref = exact(alpha2=0.0 * mu, mu=mu)
    print()
    print("| mu (alpha2 = 0) | theta0 exact | linear | 1R (prbm) | PR-3R su | PR-3R flexure |")
    print("|---|---|---|---|---|---|")
    rows = [flexure.beam(alpha2=0.0 * mu, mu=mu, method=m, **extra)
            for m, extra in (("linear", {}), ("prbm", {}), ("prbm3r", {}),
                             ("prbm3r", {"constants": "flexure"}))]
    errors = [error(r, ref) for r in rows]
    for i in range(len(mu)):
        print(f"| {mu[i]:g} | {ref['theta0'][i]:.3f} | "
              + " | ".join(f"{e[i]:.1e}" for e in errors) + " |")


def main():
    print("## Chained BCM against N\n")
    cbcm_convergence()
    print("\n## BCM against its deflection\n")
    bcm_against_deflection()
    print("\n## Pseudo-rigid-body models against the load\n")
    prbm_against_load()


if __name__ == "__main__":
    main()
