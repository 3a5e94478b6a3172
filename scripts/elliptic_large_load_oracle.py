#!/usr/bin/env python3
"""Writes tests/data/elliptic_large_loads_mpmath.csv: cantilever elastica tips at alpha2 100-1000.

An oracle for the elliptic solver beyond the 40-row grid of tests/solver/elliptic_solver_test.cpp
(alpha2 0.099-9.67), computed with mpmath alone: no flexure code and no formula taken from it.

The problem (Howell's parameters, l = 1, EI = 1): a cantilever clamped along +x at the origin,
tip force Fx = -n alpha2, Fy = alpha2 (n > 0 compresses), tip moment mu. With P = alpha2
sqrt(1 + n^2) and the force angle phi = atan2(1, -n) the elastica is
    theta'' = -P sin(phi - theta),   theta(0) = 0,   theta'(1) = mu,
and its first integral (multiply by theta', integrate from s to the tip)
    theta'^2 = mu^2 + 2P (cos(phi - theta0) - cos(phi - theta))
             = mu^2 + 4P sin(d + t/2) sin(t/2),   d = phi - theta0,  t = theta0 - theta.
On the loading branch taken here the curvature is positive along the beam (theta rises from 0 to
theta0 without an inflection; mu >= 0 acts with the force), so s can be traded for t:
    1 = int_0^theta0 dt / theta',   a/l = int cos(theta0 - t) dt / theta',
    b/l = int sin(theta0 - t) dt / theta'.
Method 1 (the values written): these three integrals by mpmath.quad (tanh-sinh) at DPS digits,
with breakpoints at t = d 10^k so that the near-logarithmic layer t ~ d is resolved, and
mpmath.findroot on log d for the d that makes the length 1 (d ~ 1e-14 at alpha2 = 1000: the tip
angle is within 1e-14 rad of the force angle, so the unknown is d, not theta0).
Method 2 (a check, not written): the initial-value problem theta(0) = 0, theta'(0) =
sqrt(mu^2 + 2P (cos d - cos phi)), x' = cos theta, y' = sin theta integrated to s = 1 with
mpmath.odefun (Taylor series) at ODE_DPS digits; theta'(1) must return mu and (x, y, theta) the
quadrature tip. The largest difference is printed and written into the file's comment block.

Run by hand (not in CI; Debian's python3-mpmath; about 70 minutes with the check on one core,
4 of them without it):
    python3 scripts/elliptic_large_load_oracle.py [--out tests/data/elliptic_large_loads_mpmath.csv]
        [--no-ode-check]
"""
import argparse
import sys
import time

import mpmath as mp

DPS = 40
ODE_DPS = 45
# (n, mu, alpha2): tension (n < 0), n = 0 and compression (n > 0) at alpha2 = 100, 300, 1000;
# end moments mu = 0.5 and 1 (with the force) at alpha2 = 100 and 1000.
CASES = [(n, "0", a) for n in ("-5", "-1", "0", "1", "5") for a in ("100", "300", "1000")] + [
    (n, "0.5", a) for n in ("-1", "0", "1") for a in ("100", "1000")
] + [("2", "1", "500")]


def integrals(n, mu, alpha2, d):
    """(length, a/l, b/l) of the monotone elastica with tip angle theta0 = phi - d."""
    P = alpha2 * mp.sqrt(1 + n * n)
    phi = mp.atan2(1, -n)
    theta0 = phi - d
    inv = lambda t: 1 / mp.sqrt(mu * mu + 4 * P * mp.sin(d + t / 2) * mp.sin(t / 2))
    # theta'^2 = mu^2 + 2P (cos d - cos(d + t)) is smallest at t_c = max(0, -d) (theta = phi),
    # where it is mu^2 - 4P sin^2(d/2): breakpoints at t_c +- s 10^k on the scales s of that
    # layer so that tanh-sinh resolves it.
    t_c = max(mp.mpf(0), -d)
    scales = [abs(d), mp.sqrt(abs(mu * mu - 4 * P * mp.sin(d / 2) ** 2) / P)]
    pts = {mp.mpf(0), theta0, t_c}
    for s in scales:
        if s == 0:
            continue
        for k in range(-3, 45):
            for t in (t_c + s * mp.mpf(10) ** k, t_c - s * mp.mpf(10) ** k):
                if 0 < t < theta0:
                    pts.add(t)
    pts = sorted(pts)
    length = mp.quad(inv, pts)
    a = mp.quad(lambda t: mp.cos(theta0 - t) * inv(t), pts)
    b = mp.quad(lambda t: mp.sin(theta0 - t) * inv(t), pts)
    return length, a, b


def solve_case(n, mu, alpha2):
    n, mu, alpha2 = mp.mpf(n), mp.mpf(mu), mp.mpf(alpha2)
    P = alpha2 * mp.sqrt(1 + n * n)
    phi = mp.atan2(1, -n)
    # The length falls as d grows. Without a moment d > 0 (d ~ 1e-30 at the largest loads); with
    # a moment mu > 0 the tip may pass the force angle (d < 0) while theta'^2 stays positive.
    # d = d_min + e^u with d_min = -2 asin(mu / (2 sqrt P)), where theta'^2 would touch zero
    # (0 without a moment); u is searched on a log scale.
    d_min = -2 * mp.asin(mu / (2 * mp.sqrt(P)))
    to_d = lambda u: d_min + mp.exp(u)
    # e^u below 10^(8 - DPS) would be lost in rounding next to d_min.
    lo, hi = mp.log(mp.mpf(10) ** (8 - DPS)), mp.log(phi * (1 - mp.mpf("1e-6")) - d_min)
    f = lambda u: integrals(n, mu, alpha2, to_d(u))[0] - 1
    f_lo, f_hi = f(lo), f(hi)
    if f_hi > 0 or f_lo < 0:
        sys.exit(f"case n={n} mu={mu} alpha2={alpha2}: no monotone solution in the bracket")
    # Regula falsi with the Illinois modification: bracketed, superlinear.
    side = 0
    for _ in range(200):
        u = (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
        fu = f(u)
        if fu > 0:
            lo, f_lo = u, fu
            if side == 1:
                f_hi /= 2
            side = 1
        else:
            hi, f_hi = u, fu
            if side == -1:
                f_lo /= 2
            side = -1
        if abs(fu) < mp.mpf(10) ** (-DPS + 5) or abs(hi - lo) < mp.mpf(10) ** (-DPS + 3):
            break
    d = to_d(u)
    length, a, b = integrals(n, mu, alpha2, d)
    return {"d": d, "theta0": phi - d, "a": a, "b": b, "length_error": length - 1}


def ode_check(n, mu, alpha2, row):
    """Largest difference between the IVP tip (mpmath.odefun) and the quadrature tip."""
    with mp.workdps(ODE_DPS):
        n, mu, alpha2 = mp.mpf(n), mp.mpf(mu), mp.mpf(alpha2)
        P = alpha2 * mp.sqrt(1 + n * n)
        phi = mp.atan2(1, -n)
        d = +row["d"]
        # theta'(0)^2 = mu^2 + 2P (cos d - cos phi), cos d - cos phi = 2 sin((phi+d)/2) sin((phi-d)/2)
        kappa0 = mp.sqrt(mu * mu + 4 * P * mp.sin((phi + d) / 2) * mp.sin((phi - d) / 2))
        rhs = lambda s, y: [y[1], -P * mp.sin(phi - y[0]), mp.cos(y[0]), mp.sin(y[0])]
        y = mp.odefun(rhs, 0, [mp.mpf(0), kappa0, mp.mpf(0), mp.mpf(0)])(1)
        return [abs(y[0] - row["theta0"]), abs(y[1] - mu), abs(y[2] - row["a"]),
                abs(y[3] - row["b"])]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="tests/data/elliptic_large_loads_mpmath.csv")
    parser.add_argument("--no-ode-check", action="store_true")
    args = parser.parse_args()
    mp.mp.dps = DPS
    rows, checks, worst_ode, worst_length = [], [], [mp.mpf(0)] * 4, mp.mpf(0)
    for n, mu, alpha2 in CASES:
        t0 = time.time()
        r = solve_case(n, mu, alpha2)
        worst_length = max(worst_length, abs(r["length_error"]))
        check = None
        if not args.no_ode_check:
            check = ode_check(n, mu, alpha2, r)
            checks.append(check)
            worst_ode = [max(w, c) for w, c in zip(worst_ode, check)]
        rows.append((n, mu, alpha2, r))
        print(f"n={n:>3} mu={mu:>3} alpha2={alpha2:>5}: d={mp.nstr(r['d'], 5)} "
              f"theta0={mp.nstr(r['theta0'], 12)} a={mp.nstr(r['a'], 12)} "
              f"b={mp.nstr(r['b'], 12)} ode check {[mp.nstr(c, 2) for c in check] if check else '-'}"
              f" ({time.time() - t0:.0f} s)", flush=True)
    if args.no_ode_check:
        check_text = "not run for this file"
    else:
        # Per row the largest difference of theta0, a, b; the two worst rows named (at the
        # largest P the IVP amplifies its own rounding by about exp(sqrt(P)), not the quadrature's).
        by_row = sorted(((max(c[0], c[2], c[3]), case) for c, case in zip(checks, CASES)),
                        reverse=True)
        named = "; ".join(f"{mp.nstr(v, 2)} at n = {c[0]}, mu = {c[1]}, alpha2 = {c[2]}"
                          for v, c in by_row[:2])
        check_text = (f"largest differences of theta0, a, b\n# {named};\n# every other row below"
                      f" {mp.nstr(by_row[2][0], 2)}; theta'(1) returns mu to"
                      f" {mp.nstr(worst_ode[1], 2)} (an error of theta'(0) grows\n# like"
                      " exp(sqrt(P)) along the beam)")
    with open(args.out, "w", encoding="ascii", newline="\n") as out:
        out.write(
            "# Cantilever elastica tips at large loads, alpha2 = 100-1000, tension and compression,\n"
            "# with and without an end moment: an oracle for the elliptic solver independent of\n"
            "# flexure's code.\n"
            "# Source: computed by scripts/elliptic_large_load_oracle.py (mpmath "
            f"{mp.__version__}, {DPS} digits) from the\n"
            "# elastica's first integral theta'^2 = mu^2 + 2P (cos(phi - theta0) - cos(phi - theta))\n"
            "# (Howell, Compliant Mechanisms, 2001, Sec. 2.7 with phi = atan2(1, -n), errata\n"
            "# eq. 2.87): length, a and b as quadratures in theta, the tip angle by root finding.\n"
            "# Checked by an mpmath.odefun integration of theta'' = -P sin(phi - theta) from the\n"
            f"# clamp ({ODE_DPS} digits): {check_text}.\n"
            "# Loads in Howell's parameters (l = 1, EI = 1): Fx = -n alpha2, Fy = alpha2, tip moment\n"
            "# mu; the loading branch without an inflection point (theta rises along the beam).\n"
            "#\n"
            "# Columns:\n"
            "#   n                load ratio, Fx = -n alpha2 (n > 0 compressive), dimensionless\n"
            "#   mu               tip moment M l/EI, dimensionless\n"
            "#   alpha2           transverse load Fy l^2/EI, dimensionless (exact as written)\n"
            "#   phi_minus_theta0 force angle minus tip angle, rad (the unknown that was solved)\n"
            "#   theta0           tip angle, rad\n"
            "#   a_over_l         tip x over l, dimensionless\n"
            "#   b_over_l         tip y over l, dimensionless\n"
            "n,mu,alpha2,phi_minus_theta0,theta0,a_over_l,b_over_l\n")
        for n, mu, alpha2, r in rows:
            out.write(",".join([n, mu, alpha2, mp.nstr(r["d"], 25, strip_zeros=False),
                                mp.nstr(r["theta0"], 25, strip_zeros=False),
                                mp.nstr(r["a"], 25, strip_zeros=False),
                                mp.nstr(r["b"], 25, strip_zeros=False)]) + "\n")
    print(f"wrote {args.out}: {len(rows)} rows; largest length residual "
          f"{mp.nstr(worst_length, 2)}; ODE check {check_text.replace(chr(10) + '# ', ' ')}")


if __name__ == "__main__":
    main()
