#!/usr/bin/python3
"""Plot `flexure dynamics` sweeps: mean, median and peak-to-peak force against drive frequency
(as the paper's Figs. 8-10 / 17-19), one curve per HDF5 file, plus the stored force histories of
the first file (as Figs. 11-13).

    /usr/bin/python3 scripts/plot_dynamics.py full.h5 no_slider.h5 no_inertia.h5 \
        --labels "Table 5" "slider mass 0" "all inertias 0" --out dynamics.png

Axis units come from the datasets' `units` attributes; the force axes name what the force is the
force of (the files' `force_of`, which must agree). Writes only the --out image (default
dynamics.png in the working directory) and prints its path. Run with Debian's python3
(matplotlib and h5py from apt).
"""
import argparse
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def unit(dataset, default):
    """The `units` attribute of `dataset` (`default` for files written before flexure stored
    units)."""
    value = dataset.attrs.get("units", default)
    return value.decode() if isinstance(value, bytes) else str(value)


def read_sweep(path):
    with h5py.File(path, "r") as f:
        data = {key: f[key][()] for key in
                ("omega", "mean_force", "median_force", "peak_to_peak_force",
                 "percent_constant_force")}
        data["omega_unit"] = unit(f["omega"], "rad/s")
        data["force_unit"] = unit(f["mean_force"], "N")
        data["mechanism"] = f.attrs["mechanism"]
        if isinstance(data["mechanism"], bytes):
            data["mechanism"] = data["mechanism"].decode()
        # `flexure dynamics --force-of half` writes "one half"; files before force_of: the whole.
        data["force_of"] = f.attrs.get("force_of", "whole symmetric mechanism")
        if isinstance(data["force_of"], bytes):
            data["force_of"] = data["force_of"].decode()
        data["history"] = []
        if "history" in f:
            for name in sorted(f["history"], key=int):
                g = f["history"][name]
                data["history"].append((float(g.attrs["omega"]), g["t"][()],
                                        g["force"][()], g["static_force"][()]))
    return data


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("files", nargs="+", help="HDF5 files written by `flexure dynamics`")
    parser.add_argument("--labels", nargs="*", help="one label per file")
    parser.add_argument("--out", default="dynamics.png", help="output image (png, pdf, svg)")
    args = parser.parse_args(argv)
    labels = args.labels or args.files
    if len(labels) != len(args.files):
        parser.error("--labels needs one label per file")
    sweeps = [read_sweep(p) for p in args.files]
    # One force axis: every file's forces must be of the same thing (one half or the whole).
    force_of = sweeps[0]["force_of"]
    mixed = [p for p, s in zip(args.files, sweeps) if s["force_of"] != force_of]
    if mixed:
        parser.error(f"{args.files[0]} has forces of the {force_of}, {mixed[0]} of "
                     f"{sweeps[args.files.index(mixed[0])]['force_of']}: write them with the same "
                     "--force-of")

    has_history = bool(sweeps[0]["history"])
    fig, axes = plt.subplots(2 if has_history else 1, 3, figsize=(14, 8 if has_history else 4),
                             squeeze=False)
    force_unit = sweeps[0]["force_unit"]
    quantities = (("mean_force", "mean force"), ("median_force", "median force"),
                  ("peak_to_peak_force", "peak-to-peak force"))
    for ax, (key, ylabel) in zip(axes[0], quantities):
        for sweep, label in zip(sweeps, labels):
            ax.plot(sweep["omega"], sweep[key], label=label)
        ax.set_xlabel(f"drive frequency omega ({sweeps[0]['omega_unit']})")
        ax.set_ylabel(f"{ylabel}, {force_of} ({force_unit})")
        ax.grid(True, alpha=0.3)
    axes[0][0].legend()
    axes[0][1].set_title(f"{sweeps[0]['mechanism']} (force of: {sweeps[0]['force_of']})")
    if has_history:
        for ax, (omega, t, force, static_force) in zip(axes[1], sweeps[0]["history"][:3]):
            period = t[-1] + t[1] if len(t) > 1 and t[1] > 0 else 1.0
            phase = t / period if period > 0 else t
            ax.plot(phase, force, label="dynamic model")
            ax.plot(phase, static_force, "--", label="static PRBM")
            ax.set_title(f"omega = {omega:g} {sweeps[0]['omega_unit']}")
            ax.set_xlabel("phase t / period (1)")
            ax.set_ylabel(f"force, {force_of} ({force_unit})")
            ax.grid(True, alpha=0.3)
        axes[1][0].legend()
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print(f"wrote {os.path.abspath(args.out)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
