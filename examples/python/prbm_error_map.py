"""PRBM tip error over the (n, alpha2) load plane, against the exact elliptic solution.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/prbm_error_map.py [--out DIR]

Solves every load twice with flexure.beam on numpy arrays (41 x 60 loads, each in one call) and
draws the relative tip error |tip_PRBM - tip_exact| / |tip deflection| of Howell's fixed-pinned
PRBM (Table 5.1 constants), with its validity limit (within_validity) outlined. Writes
prbm_error_map.png to DIR (default: the current folder) and prints the worst errors inside and
outside the limit.
"""
import argparse
import os
import warnings

import matplotlib
import matplotlib.pyplot as plt
import numpy as np

import flexure


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=".", help="folder for prbm_error_map.png")
    args = parser.parse_args()
    n = np.linspace(-2.0, 3.0, 41)[:, None]
    alpha2 = np.linspace(0.25, 15.0, 60)[None, :]
    exact = flexure.beam(n=n, alpha2=alpha2, method="elliptic")
    with warnings.catch_warnings():  # the loads outside the PRBM's limits: drawn, not warned
        warnings.simplefilter("ignore", flexure.FlexureWarning)
        prbm = flexure.beam(n=n, alpha2=alpha2, method="prbm")
    ok = exact["converged"] & prbm["converged"]
    deflection = np.hypot(1.0 - exact["a_over_l"], exact["b_over_l"])
    error = np.hypot(prbm["a_over_l"] - exact["a_over_l"],
                     prbm["b_over_l"] - exact["b_over_l"]) / deflection
    error = np.where(ok, error, np.nan)
    inside = prbm["within_validity"] & ok
    print(f"{ok.sum()} of {ok.size} loads solved by both; worst relative tip error "
          f"{np.nanmax(np.where(inside, error, np.nan)):.3g} inside the PRBM's validity limit, "
          f"{np.nanmax(np.where(~inside, error, np.nan)):.3g} outside")

    matplotlib.rcParams["font.size"] = 8
    fig, ax = plt.subplots(figsize=(6, 4))
    extent = [alpha2.min(), alpha2.max(), n.min(), n.max()]
    image = ax.imshow(np.log10(error), origin="lower", aspect="auto", extent=extent,
                      cmap="viridis")
    ax.contour(np.broadcast_to(alpha2, error.shape), np.broadcast_to(n, error.shape),
               inside.astype(float), levels=[0.5], colors="white", linewidths=1.2)
    fig.colorbar(image, ax=ax, label="log10 relative tip error of the PRBM")
    ax.set_xlabel("alpha2 = P l^2/EI")
    ax.set_ylabel("load ratio n (n > 0 compressive)")
    ax.set_title("Fixed-pinned PRBM against the elliptic solution (white: validity limit)")
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "prbm_error_map.png")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
