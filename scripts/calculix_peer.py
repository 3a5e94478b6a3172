#!/usr/bin/python3
"""CalculiX peer for `flexure bench`: the cantilever problems solved with B32R beam elements and
NLGEOM, read back into the same HDF5 results file (docs/benchmarks.md, docs/hdf5-schema.md).

Usage:
  /usr/bin/python3 scripts/calculix_peer.py FILE.h5 [--elements 10,20,40] [--problems LIST]
                                            [--max-points K]

For every load of <problem>/reference in FILE.h5 and every mesh of N B32R elements (2N+1 nodes)
it writes an input deck, runs `ccx` (one thread), parses the tip displacement from the .dat file
and adds the group <problem>/calculix_B32R_N<N> with the datasets of the schema: a/l, b/l,
theta0, the error against the reference, the WALL TIME of the ccx process (deck writing and
parsing excluded; process start and file I/O included: that is what a user of the peer pays),
status and message. The file is rewritten through a temporary copy and an atomic rename, so it is
complete or unchanged. If ccx is missing the run says so and skips (exit 0).

Model: length 1, square section 1e-3 x 1e-3, E = 1.2e13 so that EI = 1 (Howell's nondimensional
beam, loads = alpha2 etc.); Poisson's ratio 0 so that ccx's expansion of the beam into 3-D
20-node bricks bends with exactly EI (nu = 0.3 stiffens it by about 1 %); EA/EI = 1.2e7 keeps
the axial strain below 2e-6. The out-of-plane displacement is fixed at every node. Dead loads
(*CLOAD keeps its direction). theta0 is the chord angle of the last half element (tip node and
its mid-side node): an approximation good to about (element length)^2, so error_theta0 of this
group measures that too.

Supported problems: cantilever_force (Fx = -n alpha2, Fy = alpha2), tip_moment (mu),
force_and_moment.
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

SUPPORTED = ("cantilever_force", "tip_moment", "force_and_moment")
STATUS_CONVERGED, STATUS_NOT_CONVERGED, STATUS_ERROR = 0, 1, 2
E_MODULUS = 1.2e13  # with the 1e-3 square section: EI = 1
SIDE = 1e-3


def write_deck(path, elements, fx, fy, moment):
    nodes = 2 * elements + 1
    lines = ["*HEADING", "flexure CalculiX peer: cantilever l = 1, EI = 1", "*NODE, NSET=NALL"]
    lines += [f"{i + 1}, {i / (nodes - 1):.15g}, 0, 0" for i in range(nodes)]
    lines += ["*NSET, NSET=TIPS", f"{nodes - 1}, {nodes}"]
    lines += ["*ELEMENT, TYPE=B32R, ELSET=EALL"]
    lines += [f"{e + 1}, {2 * e + 1}, {2 * e + 2}, {2 * e + 3}" for e in range(elements)]
    lines += ["*MATERIAL, NAME=M", "*ELASTIC", f"{E_MODULUS:.6g}, 0.0",
              "*BEAM SECTION, ELSET=EALL, MATERIAL=M, SECTION=RECT", f"{SIDE}, {SIDE}",
              "0, 0, 1", "*BOUNDARY", "1, 1, 6", "NALL, 3, 3",
              "*STEP, NLGEOM, INC=10000", "*STATIC", "0.02, 1.0, 1e-7, 0.05", "*CLOAD"]
    if fx:
        lines.append(f"{nodes}, 1, {fx:.15g}")
    if fy:
        lines.append(f"{nodes}, 2, {fy:.15g}")
    if moment:
        lines.append(f"{nodes}, 6, {moment:.15g}")
    lines += ["*NODE PRINT, NSET=TIPS", "U", "*END STEP"]
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def parse_tip(dat_path, elements):
    """(a/l, b/l, theta0) from the last displacement block of the .dat file, or None."""
    text = open(dat_path).read()
    blocks = text.split("displacements (vx,vy,vz)")
    if len(blocks) < 2 or "time  0.1000000E+01" not in blocks[-1]:
        return None
    rows = {}
    for line in blocks[-1].splitlines()[1:]:
        parts = line.split()
        if len(parts) == 4 and parts[0].isdigit():
            rows[int(parts[0])] = [float(v) for v in parts[1:]]
    nodes = 2 * elements + 1
    if nodes not in rows or nodes - 1 not in rows:
        return None
    x_tip = 1.0 + rows[nodes][0]
    y_tip = rows[nodes][1]
    x_mid = (nodes - 2) / (nodes - 1) + rows[nodes - 1][0]
    y_mid = rows[nodes - 1][1]
    return x_tip, y_tip, math.atan2(y_tip - y_mid, x_tip - x_mid)


def solve(workdir, elements, n, alpha2, mu):
    deck = os.path.join(workdir, "peer")
    write_deck(deck + ".inp", elements, -n * alpha2, alpha2, mu)
    for suffix in (".dat", ".sta", ".frd"):
        if os.path.exists(deck + suffix):
            os.remove(deck + suffix)
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1")
    start = time.perf_counter()
    proc = subprocess.run(["ccx", "-i", "peer"], cwd=workdir, capture_output=True, text=True,
                          env=env, timeout=600)
    seconds = time.perf_counter() - start
    tip = parse_tip(deck + ".dat", elements) if os.path.exists(deck + ".dat") else None
    if proc.returncode != 0 or tip is None:
        tail = " ".join((proc.stdout + proc.stderr).strip().splitlines()[-3:])
        status = STATUS_ERROR if proc.returncode != 0 else STATUS_NOT_CONVERGED
        return status, None, seconds, f"ccx did not reach load factor 1: {tail}"[:400]
    return STATUS_CONVERGED, tip, seconds, ""


def ccx_version():
    try:
        out = subprocess.run(["ccx", "-v"], capture_output=True, text=True, timeout=30).stdout
        return out.strip().splitlines()[-1] if out.strip() else "ccx"
    except (OSError, subprocess.SubprocessError):
        return "ccx"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("file")
    ap.add_argument("--elements", default="10,20,40")
    ap.add_argument("--problems", default="cantilever_force")
    ap.add_argument("--max-points", type=int, default=0, help="first K loads only (0 = all)")
    args = ap.parse_args()
    if shutil.which("ccx") is None:
        print("calculix_peer: ccx not found (Debian package calculix-ccx); peer skipped")
        return 0
    meshes = [int(x) for x in args.elements.split(",") if x]
    problems = [p for p in args.problems.split(",") if p]
    for p in problems:
        if p not in SUPPORTED:
            print(f"calculix_peer: --problems: '{p}' is not supported ({', '.join(SUPPORTED)})",
                  file=sys.stderr)
            return 2
    version = ccx_version()
    results = {}
    with h5py.File(args.file, "r") as f, tempfile.TemporaryDirectory() as work:
        for problem in problems:
            if problem not in f:
                print(f"calculix_peer: {problem} not in {args.file}; skipped")
                continue
            ref = f[problem]["reference"]
            count = len(ref["alpha2"]) if args.max_points <= 0 else min(args.max_points,
                                                                         len(ref["alpha2"]))
            for elements in meshes:
                rows = []
                for i in range(count):
                    n, a2, mu = (float(ref[k][i]) for k in ("load_ratio_n", "alpha2", "mu"))
                    status, tip, seconds, message = solve(work, elements, n, a2, mu)
                    rows.append((n, a2, mu, status, tip, seconds, message, i))
                    print(f"{problem} N={elements} n={n:g} alpha2={a2:g} mu={mu:g}: "
                          f"{'ok' if status == 0 else 'FAILED'} {seconds:.2f} s", flush=True)
                results[(problem, elements)] = rows

    nan = float("nan")
    tmp = args.file + ".ccx-tmp"
    shutil.copyfile(args.file, tmp)
    try:
        with h5py.File(tmp, "r+") as f:
            for (problem, elements), rows in results.items():
                ref = f[problem]["reference"]
                name = f"calculix_B32R_N{elements:03d}"
                if name in f[problem]:
                    del f[problem][name]
                g = f[problem].create_group(name)
                cols = {k: [] for k in ("load_ratio_n", "alpha2", "mu", "a_over_l", "b_over_l",
                                        "theta0", "error_position", "error_relative",
                                        "error_theta0", "seconds")}
                status_col, messages = [], []
                for n, a2, mu, status, tip, seconds, message, i in rows:
                    cols["load_ratio_n"].append(n)
                    cols["alpha2"].append(a2)
                    cols["mu"].append(mu)
                    cols["seconds"].append(seconds)
                    ok = status == STATUS_CONVERGED
                    a, b, th = tip if ok else (nan, nan, nan)
                    cols["a_over_l"].append(a)
                    cols["b_over_l"].append(b)
                    cols["theta0"].append(th)
                    ra, rb, rth = (float(ref[k][i]) for k in ("a_over_l", "b_over_l", "theta0"))
                    ref_ok = int(ref["status"][i]) == STATUS_CONVERGED
                    if ok and not ref_ok:
                        status = 3
                    e = math.hypot(a - ra, b - rb) if ok and ref_ok else nan
                    cols["error_position"].append(e)
                    cols["error_relative"].append(e / max(math.hypot(ra - 1.0, rb), 1e-9))
                    cols["error_theta0"].append(abs(th - rth) if ok and ref_ok else nan)
                    status_col.append(status)
                    messages.append(message)
                for k, v in cols.items():
                    g.create_dataset(k, data=np.asarray(v, dtype="<f8"))
                size = len(rows)
                g.create_dataset("status", data=np.asarray(status_col, dtype="<i4"))
                g.create_dataset("repeats", data=np.ones(size, dtype="<i4"))
                g.create_dataset("iterations", data=np.zeros(size, dtype="<i4"))
                g.create_dataset("within_validity", data=np.full(size, -1, dtype="<i4"))
                g.create_dataset("message", data=messages,
                                 dtype=h5py.string_dtype(encoding="utf-8"))
                # Every dataset carries units and a description (docs/hdf5-schema.md): the same
                # as the reference group's dataset of that name, except where ccx differs.
                for k in g:
                    for attr in ("units", "description"):
                        if k in ref and attr in ref[k].attrs:
                            g[k].attrs[attr] = ref[k].attrs[attr]
                g["seconds"].attrs["description"] = "wall time of the ccx process for this load"
                g["repeats"].attrs["description"] = "number of timed solves (1: one ccx run)"
                g["iterations"].attrs["description"] = "not recorded for ccx (0)"
                g["within_validity"].attrs["units"] = "1"
                g["within_validity"].attrs["description"] = "-1: not a PRBM method"
                g.attrs["family"] = "calculix"
                g.attrs["backend"] = version
                g.attrs["tolerance"] = 0.0  # ccx's default residual control (*STATIC)
                g.attrs["elements"] = np.int64(elements)
                g.attrs["increments"] = np.int64(0)
        os.replace(tmp, args.file)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)
    print(f"calculix_peer: added {len(results)} groups to {args.file}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
