#!/usr/bin/python3
"""Plot one stroke of `flexure mechanism analyze NAME --out FILE.h5` (schema: docs/hdf5-schema.md,
"flexure mechanism analyze"): slider force of the PRBM and of the exact model against the slider
displacement, the PRBM force error relative to the exact model in a second panel, the PRBM
validity limit as a vertical line where the file has one, and a stress panel: the PRBM and (where
the exact model ran) the exact stress of every flexure with the material's yield strength as a
horizontal line (--no-stress leaves the panel out). Axis units come from the datasets' `units`
attributes; the force axis names what the force is the force of (the file's `force_of`: one half
of the symmetric mechanism or the whole). The title names the design and its percent constant
force.

    flexure mechanism analyze 1A-lpp --method exact --out lpp.h5
    /usr/bin/python3 scripts/plot_mechanism.py lpp.h5 --out lpp.png

Writes only the --out image (default mechanism.png in the working directory) and prints its path.

Runs under Debian's /usr/bin/python3 with the apt packages python3-matplotlib and python3-h5py
(scripts/install-deps.sh). Exits 1 with a message when they are missing or the file is not a
mechanism stroke; the image is written whole or not at all (temporary file + rename).
"""
import argparse
import math
import os
import sys
import tempfile


def fail(message):
    print(f"plot_mechanism.py: error: {message}", file=sys.stderr)
    sys.exit(1)


try:
    import h5py
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError as e:  # pragma: no cover - depends on the machine
    fail(f"{e.name or e} is not importable by {sys.executable}; install the Debian packages "
         "python3-matplotlib and python3-h5py (apt-get install python3-matplotlib python3-h5py) "
         "and run the script with /usr/bin/python3")


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


# Units shown on the axes: lengths in mm and stresses in MPa read better than m and Pa.
DISPLAY = {"m": (1e3, "mm"), "Pa": (1e-6, "MPa")}


def display(f, name, default):
    """(scale, unit shown) for dataset `name`, from its `units` attribute (`default` for files
    written before flexure stored units)."""
    units = text(f[name].attrs.get("units", default)) if name in f else default
    return DISPLAY.get(units, (1.0, units))


def read_stroke(path):
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        fail(f"cannot read {path} as HDF5: {e}")
    with f:
        for key in ("displacement", "force_prbm"):
            if key not in f:
                fail(f"{path} has no dataset '{key}': not written by `flexure mechanism analyze "
                     "--out`")
        data = {
            "displacement": f["displacement"][()],
            "force_prbm": f["force_prbm"][()],
            "force_exact": f["force_exact"][()] if "force_exact" in f else None,
            "mechanism": text(f.attrs.get("mechanism", os.path.basename(path))),
            # `flexure mechanism analyze` reports one half unless --force-of whole (or the design
            # file's force_of) says otherwise; files written before the attribute: one half.
            "force_of": text(f.attrs.get("force_of", "one half")),
            "config": text(f.attrs.get("config", "")),
            "pcf_prbm": f.attrs.get("percent_constant_force_prbm"),
            "pcf_exact": f.attrs.get("percent_constant_force_exact"),
            # 1 where that force is zero or changes sign: its percentage is then 0 by
            # definition (docs/mechanisms.md "Percent constant force"); absent in older files.
            "sign_prbm": f.attrs.get("force_changes_sign_prbm"),
            "vanish_prbm": f.attrs.get("force_vanishes_prbm"),
            "sign_exact": f.attrs.get("force_changes_sign_exact"),
            "vanish_exact": f.attrs.get("force_vanishes_exact"),
            "validity": f.attrs.get("prbm_validity_limit"),
            # What is outside Table 5.1 there and the PRBM's force error (absent in older files).
            "validity_quantity": text(f.attrs.get("prbm_validity_quantity", "")),
            "validity_value": f.attrs.get("prbm_validity_value"),
            "validity_error": f.attrs.get("prbm_force_error_at_validity_limit"),
            "within_validity": (f["prbm_within_validity"][()]
                                if "prbm_within_validity" in f else None),
            # Absent in files written before the design was stored.
            "yield": (float(f["design/yield_strength"][()])
                      if "design/yield_strength" in f else None),
            "length": display(f, "displacement", "m"),
            "force": display(f, "force_prbm", "N"),
            "stress_unit": display(f, "stress_prbm_pivot1", "Pa"),
            "stress": {},
            "stress_exact": {},
        }
        for pivot in (1, 2, 3):
            for model, key in (("prbm", "stress"), ("exact", "stress_exact")):
                name = f"stress_{model}_pivot{pivot}"
                if name in f:
                    data[key][pivot] = f[name][()]
                    data["stress_unit"] = display(f, name, "Pa")
    return data


def save_atomically(fig, out):
    directory = os.path.dirname(os.path.abspath(out))
    extension = os.path.splitext(out)[1].lstrip(".").lower() or "png"
    fd, tmp = tempfile.mkstemp(prefix=".plot_mechanism-", suffix="." + extension, dir=directory)
    os.close(fd)
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(tmp, 0o666 & ~umask)  # mkstemp creates 0600; give the image the usual mode
    try:
        fig.savefig(tmp, dpi=120, format=extension)
        os.replace(tmp, out)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file", help="HDF5 file written by `flexure mechanism analyze --out`")
    parser.add_argument("--out", default="mechanism.png", help="output image (png, pdf, svg)")
    parser.add_argument("--stress", action="store_true",
                        help="draw the stress panel (the default; kept for older command lines)")
    parser.add_argument("--no-stress", action="store_true", help="leave the stress panel out")
    args = parser.parse_args(argv)
    d = read_stroke(args.file)

    length_scale, length_unit = d["length"]
    force_scale, force_unit = d["force"]
    stress_scale, stress_unit = d["stress_unit"]
    dx = d["displacement"] * length_scale
    exact = d["force_exact"]
    stress_panel = not args.no_stress and bool(d["stress"] or d["stress_exact"])
    panels = 1 + (exact is not None) + stress_panel
    fig, axes = plt.subplots(panels, 1, figsize=(7, 2.2 + 2.3 * panels), sharex=True,
                             squeeze=False)
    axes = axes[:, 0]
    ax = axes[0]
    ax.plot(dx, d["force_prbm"] * force_scale, "o-", ms=3, label="PRBM")
    if exact is not None:
        ax.plot(dx, exact * force_scale, "s-", ms=3, label="exact (elastica)")
    ax.set_ylabel(f"slider force F, {d['force_of']} ({force_unit})")
    ax.grid(True, alpha=0.3)
    row = 1
    if exact is not None:
        err = 100.0 * (d["force_prbm"] - exact) / exact
        axes[row].plot(dx, err, "o-", ms=3, color="C2")
        axes[row].axhline(0.0, color="0.5", lw=0.8)
        axes[row].set_ylabel("PRBM force error (%)")
        axes[row].grid(True, alpha=0.3)
        row += 1
    if stress_panel:
        sa = axes[row]
        for pivot, sigma in sorted(d["stress"].items()):
            sa.plot(dx, sigma * stress_scale, "--", color=f"C{pivot - 1}",
                    label=f"pivot {pivot} PRBM")
        for pivot, sigma in sorted(d["stress_exact"].items()):
            sa.plot(dx, sigma * stress_scale, "-", color=f"C{pivot - 1}",
                    label=f"pivot {pivot} exact")
        if d["yield"] is not None:
            sa.axhline(d["yield"] * stress_scale, color="k", ls=":", lw=1.2,
                       label="yield strength")
        sa.set_ylabel(f"largest stress ({stress_unit})")
        sa.legend(fontsize=7, ncol=2)
        sa.grid(True, alpha=0.3)
    if d["validity"] is not None:
        label = "PRBM outside Table 5.1"
        names = {"load_ratio_n": "n", "load_angle_phi": "phi [deg]", "Theta": "Theta [deg]"}
        if d["validity_quantity"] in names and d["validity_value"] is not None:
            label += f" ({names[d['validity_quantity']]} = {float(d['validity_value']):.3g} at the first"
            error = d["validity_error"]
            if error is not None and math.isfinite(float(error)):
                label += f"; PRBM force error there {100 * float(error):.1f} %"
            label += ")"
        inside = d["within_validity"]
        if inside is not None and len(inside) == len(dx):
            # The points outside, each shaded out to half-way to its neighbours.
            edges = [dx[0] - 0.5 * (dx[1] - dx[0]) if len(dx) > 1 else dx[0]]
            edges += [0.5 * (a + b) for a, b in zip(dx[:-1], dx[1:])]
            edges += [dx[-1] + 0.5 * (dx[-1] - dx[-2]) if len(dx) > 1 else dx[-1]]
            for a in axes:
                for k, flag in enumerate(inside):
                    if int(flag) == 0:
                        a.axvspan(edges[k], edges[k + 1], color="C3", alpha=0.12, lw=0)
            axes[0].fill_between([], [], color="C3", alpha=0.12, label=label)
        else:  # files without the per-point flags: the first point outside
            for a in axes:
                a.axvline(float(d["validity"]) * length_scale, color="C3", ls="--", lw=1)
            axes[0].plot([], [], color="C3", ls="--", label=label)
    axes[0].legend(fontsize=8)
    axes[-1].set_xlabel(f"slider displacement Delta x ({length_unit})")

    def note(model):
        if d[f"sign_{model}"] is not None and int(d[f"sign_{model}"]):
            return " (force changes sign)"
        if d[f"vanish_{model}"] is not None and int(d[f"vanish_{model}"]):
            return " (force vanishes)"
        return ""

    pcf = f"PRBM {float(d['pcf_prbm']):.2f} %{note('prbm')}" if d["pcf_prbm"] is not None else ""
    if d["pcf_exact"] is not None:
        pcf += f", exact {float(d['pcf_exact']):.2f} %{note('exact')}"
    config = f" ({d['config']})" if d["config"] else ""
    fig.suptitle(f"{d['mechanism']}{config}: percent constant force {pcf}", fontsize=10)
    fig.tight_layout()
    try:
        save_atomically(fig, args.out)
    except OSError as e:
        # e.g. the directory of --out does not exist: a message, not a traceback (exit 1 as above)
        print(f"plot_mechanism.py: error: cannot write {args.out}: {e.strerror or e}", file=sys.stderr)
        return 1
    print(f"wrote {os.path.abspath(args.out)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
