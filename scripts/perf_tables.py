#!/usr/bin/env python3
"""Regenerates the measured tables of docs/performance.md from one benchmark run.

    python3 scripts/perf_tables.py --build build            # run the benchmarks, rewrite tables
    python3 scripts/perf_tables.py --build build --only elliptic_bench sweep_bench
    python3 scripts/perf_tables.py --from-json runs/        # tables from saved JSON, no run

Every table between the markers

    <!-- perf-table: NAME -->
    ...
    <!-- end perf-table -->

in docs/performance.md is replaced by the medians of one run of benchmark program NAME (Google
Benchmark, --benchmark_repetitions, medians of CPU and wall time) with, where the program has a
reference benchmark (REFERENCES below), each row's CPU-time ratio to it measured in the same run.
The `startup` table times whole processes: `flexure beam --alpha2 2 --json` against `true` (an
empty process), the median of alternating runs; the `python_beam` table the vectorised
flexure.beam (Debian's /usr/bin/python3, the module in BUILD/python) against `flexure sweep beam`
on the same loads; the `python_scalar` table one scalar flexure.beam and flexure.solve_beam against
solve_beam in C++ (beam_stability_bench's BM_SolveBeamAuto) and the command line run in-process; the `sweep_verdict` table the shooting sweep of issue 27 with and without the
stability verdict (this build and --baseline); the `edges` table the commands of issue 27 as a user runs them (a shooting
sweep, the guided chain, the chain's element count), with the GSL + Brent yardstick of
shooting_sweep_bench measured in the same run, and the same commands of an older build given by
--baseline BUILD (the before column); the `general_mechanisms` table the shipped general
mechanisms of issue 31 by both models (times, equilibria, limit points). No number in a generated table is typed by hand.
Standard library only; the raw JSON of each program is kept with --keep DIR.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

from doc_blocks import rewrite_blocks

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = os.path.join(ROOT, "docs", "performance.md")

# The yardstick of each program: its other rows are divided by this one's CPU time.
REFERENCES = {
    "elliptic_bench": "BM_GslBrentReference",
    # rk:2 is GSL's rk8pd, the default integrator, on the issue-14 goal case (n = 0, alpha2 = 3).
    "shooting_bench": "BM_CantileverDirect/rtol_exp:9/rk:2",
    # The corrected chain at its default (one increment to start, coarse-chain path), N = 100.
    "chain_bench": "BM_ChainCorrected/N:100/inc:1/coarse:1",
    "mechanism_bench": "BM_ExactStroke50/1A-lpp",
    # One elliptic forward solve of the same cantilever load: what a verdict adds to a solve.
    "stability_bench": "BM_EllipticSolve",
    # The elliptic solve of the same load without the verdict: what the verdict adds to an answer.
    "beam_stability_bench": "BM_SolveBeam/load:0/verdict:0",
    # Issue 27: the shooting sweep per point against the GSL + Brent yardstick.
    "shooting_sweep_bench": "BM_GslBrentReference",
}


def run_program(build, name, repetitions, keep, only=None):
    exe = os.path.join(build, "benchmarks", name)
    if not os.access(exe, os.X_OK):
        sys.exit(f"perf_tables.py: {exe} is not built (cmake --build {build} --target {name})")
    argv = [exe, f"--benchmark_repetitions={repetitions}",
            "--benchmark_report_aggregates_only=true", "--benchmark_format=json"]
    if only:
        argv.append(f"--benchmark_filter={only}")
    out = subprocess.run(argv, capture_output=True, text=True, check=True).stdout
    if keep:
        os.makedirs(keep, exist_ok=True)
        with open(os.path.join(keep, name + ".json"), "w", encoding="utf-8") as f:
            f.write(out)
    return json.loads(out)


def medians(report):
    """name -> (cpu, wall, unit) of the median aggregate."""
    rows = {}
    for b in report["benchmarks"]:
        if b.get("aggregate_name", "median") != "median":
            continue
        rows[b.get("run_name", b["name"])] = (b["cpu_time"], b["real_time"], b["time_unit"])
    return rows


def to_seconds(value, unit):
    return value * {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[unit]


def pretty(seconds):
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6), ("ns", 1e-9)):
        if seconds >= scale:
            return f"{seconds / scale:.3g} {unit}"
    return f"{seconds / 1e-9:.3g} ns"


def repetitions_of(report):
    """Google Benchmark records the repetitions on each entry, not at the top."""
    for b in report.get("benchmarks", []):
        if "repetitions" in b:
            return b["repetitions"]
    return report.get("repetitions", "?")


def benchmark_table(name, report):
    rows = medians(report)
    reference = REFERENCES.get(name)
    ref_cpu = None
    if reference and reference in rows:
        cpu, _, unit = rows[reference]
        ref_cpu = to_seconds(cpu, unit)
    context = report.get("context", {})
    lines = [f"`{name}`, {context.get('num_cpus', '?')} CPUs, "
             f"{context.get('date', '')[:10]}; medians of "
             f"{repetitions_of(report)} repetitions"
             + (f"; ratio = CPU time / `{reference}` in the same run" if ref_cpu else "") + ":",
             "",
             "| benchmark | CPU (median) | wall (median) |" + (" ratio |" if ref_cpu else ""),
             "|---|---|---|" + ("---|" if ref_cpu else "")]
    for bench, (cpu, wall, unit) in rows.items():
        cpu_s, wall_s = to_seconds(cpu, unit), to_seconds(wall, unit)
        line = f"| `{bench}` | {pretty(cpu_s)} | {pretty(wall_s)} |"
        if ref_cpu:
            line += f" {cpu_s / ref_cpu:.3g} |"
        lines.append(line)
    return "\n".join(lines)


def startup_table(build, runs):
    flexure = os.path.join(build, "flexure")
    commands = {"flexure beam --alpha2 2 --json": [flexure, "beam", "--alpha2", "2", "--json"],
                "flexure --version": [flexure, "--version"],
                "true (an empty process)": ["true"]}
    times = {k: [] for k in commands}
    for _ in range(runs):  # alternating, so that drift of the machine hits every command alike
        for label, argv in commands.items():
            start = time.perf_counter()
            subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
            times[label].append(time.perf_counter() - start)
    base = statistics.median(times["true (an empty process)"])
    lines = [f"Whole processes, wall time, median of {runs} alternating runs:", "",
             "| command | wall (median) | ratio to `true` |", "|---|---|---|"]
    for label, t in times.items():
        m = statistics.median(t)
        lines.append(f"| `{label}` | {pretty(m)} | {m / base:.3g} |")
    return "\n".join(lines)


PYTHON_BEAM = """
import sys, time, numpy, flexure
points, threads = int(sys.argv[1]), int(sys.argv[2])
alpha2 = numpy.linspace(0.1, 10.0, points)
start = time.perf_counter()
r = flexure.beam(alpha2=alpha2, method="elliptic", stability="off", threads=threads)
elapsed = time.perf_counter() - start
assert r["converged"].all()
print(elapsed)
"""


PYTHON_CHAIN = """
import sys, time, numpy, flexure
start = time.process_time()
r = flexure.beam(alpha2=numpy.full(400, 10.0), method="chain", elements=int(sys.argv[1]),
                 threads=1)
elapsed = time.process_time() - start
assert r["converged"].all()
print(elapsed / 400)
"""


def python_beam_table(build, runs, points=1_000_000):
    """The vectorised flexure.beam against `flexure sweep beam` on the same 10^6 loads (issue 15:
    within 1.5x per point): the solve time each reports, alternating, one pair per run."""
    import tempfile
    flexure = os.path.join(build, "flexure")
    env = dict(os.environ, PYTHONPATH=os.path.join(build, "python"))
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for threads in (1, 2):
            sweep, module, ratios = [], [], []
            for _ in range(runs):
                out = subprocess.run(
                    [flexure, "sweep", "beam", "--alpha2", f"0.1:10:{points}", "--method",
                     "elliptic", "--stability", "off", "--threads", str(threads), "--out",
                     os.path.join(tmp, "s.h5"), "--json"],
                    capture_output=True, text=True, check=True).stdout
                sweep.append(json.loads(out)["seconds"])
                module.append(float(subprocess.run(
                    ["/usr/bin/python3", "-c", PYTHON_BEAM, str(points), str(threads)],
                    capture_output=True, text=True, check=True, env=env).stdout))
                ratios.append(module[-1] / sweep[-1])
            rows.append((threads, statistics.median(sweep), statistics.median(module),
                         statistics.median(ratios)))
    lines = [f"{points} elliptic loads, alpha2 from 0.1 to 10, without the stability verdict "
             f"(`--stability off`, `stability=\"off\"`: its cost is in \"Stability verdict\"); "
             f"solve time as each reports it (the sweep's includes writing its file), medians of "
             f"{runs} alternating pairs:", "",
             "| threads | `flexure sweep beam` | `flexure.beam(alpha2=array)` | ratio |",
             "|---|---|---|---|"]
    for threads, t_sweep, t_module, ratio in rows:
        lines.append(f"| {threads} | {pretty(t_sweep)} | {pretty(t_module)} | {ratio:.3g} |")
    return "\n".join(lines)


PYTHON_SCALAR = """
import json, sys, time, timeit, flexure
from flexure import _command
number, repeat = int(sys.argv[1]), int(sys.argv[2])
off = flexure.BeamProblem(alpha2=2.0, judge_stability=False)
on = flexure.BeamProblem(alpha2=2.0)
calls = {
    "beam": lambda: flexure.beam(alpha2=2.0),
    "beam_off": lambda: flexure.beam(alpha2=2.0, stability="off"),
    "solve_beam": lambda: flexure.solve_beam(on),
    "solve_beam_off": lambda: flexure.solve_beam(off),
    # What flexure.beam did before: the command line run in-process.
    "cli": lambda: _command.run(["beam"], {"alpha2": 2.0}, switches={"stable"}),
    "cli_off": lambda: _command.run(["beam"], {"alpha2": 2.0, "stability": "off"},
                                    switches={"stable"}),
}
# CPU time of this process (as the C++ column's), not wall time: the machine is shared.
best = {name: min(timeit.repeat(f, timer=time.process_time, number=number, repeat=repeat))
        / number
        for name, f in calls.items()}
print(json.dumps(best))
"""


def python_scalar_table(build, repetitions, number=2000, repeat=7):
    """One scalar beam from Python (issue 28: within 20 us) against solve_beam in C++ (Google
    benchmark BM_SolveBeamAuto of beam_stability_bench), with and without the stability verdict,
    in one run: the C++ medians, then each Python call by timeit (best of `repeat` x `number`)."""
    report = run_program(build, "beam_stability_bench", repetitions, None,
                         only="BM_SolveBeamAuto")
    cpp = {name: to_seconds(cpu, unit) for name, (cpu, _wall, unit) in medians(report).items()}
    env = dict(os.environ, PYTHONPATH=os.path.join(build, "python"))
    out = subprocess.run(["/usr/bin/python3", "-c", PYTHON_SCALAR, str(number), str(repeat)],
                         capture_output=True, text=True, check=True, env=env).stdout
    py = json.loads(out)
    rows = [("with the verdict (default)", "BM_SolveBeamAuto/verdict:1", ""),
            ("without (`stability=\"off\"`)", "BM_SolveBeamAuto/verdict:0", "_off")]
    lines = [f"`flexure beam --alpha2 2` (method auto: the elliptic solution) from Python, each "
             f"call's CPU time by `timeit` (best of {repeat} x {number}); C++ = `solve_beam` "
             f"(`BM_SolveBeamAuto`, CPU median of {repetitions}); ratio = Python / C++, all in one "
             f"run:", "",
             "| stability verdict | C++ `solve_beam` | `flexure.solve_beam(problem)` | "
             "`flexure.beam(alpha2=2.0)` | the command line in-process (before) | "
             "ratio `flexure.beam` | ratio before |",
             "|---|---|---|---|---|---|---|"]
    for label, bench, suffix in rows:
        c = cpp[bench]
        lines.append(f"| {label} | {pretty(c)} | {pretty(py['solve_beam' + suffix])} | "
                     f"{pretty(py['beam' + suffix])} | {pretty(py['cli' + suffix])} | "
                     f"{py['beam' + suffix] / c:.3g} | {py['cli' + suffix] / c:.3g} |")
    return "\n".join(lines)


def child_cpu():
    """CPU seconds (user + system) of the finished child processes so far."""
    import resource
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_timed(argv):
    """(wall seconds, CPU seconds, exit code, stdout) of one whole process. The CPU time is the
    task clock of `perf stat` where perf is installed (nanoseconds; getrusage's child times move in
    scheduler ticks, too coarse for the 0.1 ms differences of the element counts), else
    getrusage."""
    import shutil
    import tempfile
    perf = shutil.which("perf")
    with tempfile.NamedTemporaryFile(suffix=".perf") as stat:
        command = ([perf, "stat", "-x,", "-e", "task-clock", "-o", stat.name] + argv
                   if perf else argv)
        cpu0, start = child_cpu(), time.perf_counter()
        p = subprocess.run(command, capture_output=True, text=True)
        wall, cpu = time.perf_counter() - start, child_cpu() - cpu0
        if perf:
            for line in open(stat.name, encoding="utf-8"):
                fields = line.strip().split(",")
                if len(fields) > 2 and fields[2].startswith("task-clock") and fields[1] == "msec":
                    cpu = float(fields[0]) * 1e-3
    return wall, cpu, p.returncode, p.stdout


def flexure_version(build):
    out = subprocess.run([os.path.join(build, "flexure"), "--version"], capture_output=True,
                         text=True).stdout.strip()
    return out.split("(")[-1].rstrip(")") if "(" in out else out


SWEEP = ["sweep", "beam", "--method", "shooting", "--n", "0", "--alpha2"]
GUIDED = [("3.662974688762594", "12.458088565233949", "-0.42576506449933227"),
          ("1.656626959124937", "8.95598052442481", "0.06897238676232442"),
          ("4.132632167956947", "14.966530943697453", "0.456109405479435")]


def sweep_per_point(build, tmp, runs, threads, n="0", extra=()):
    """CPU per point of the issue's sweep (500 points less a 1-point sweep of the same command, so
    that start-up and the file cancel) and the wall time per point it reports itself. `n` and
    `extra` (e.g. --stability off) change the command."""
    flexure = os.path.join(build, "flexure")
    sweep = SWEEP[:5] + [n] + SWEEP[6:]
    cpu, wall = [], []
    for _ in range(runs):
        _, full, rc, out = run_timed([flexure] + sweep + ["0.5:10:500", "--threads", str(threads),
                                                          "--out", os.path.join(tmp, "s.h5"),
                                                          "--json"] + list(extra))
        _, one, rc1, _ = run_timed([flexure] + sweep + ["0.5:10:1", "--threads", "1", "--out",
                                                        os.path.join(tmp, "1.h5")] + list(extra))
        if rc or rc1:
            sys.exit(f"perf_tables.py: the sweep failed in {build}")
        cpu.append((full - one) / 499)
        wall.append(json.loads(out)["seconds"] / 500)
    return statistics.median(cpu), statistics.median(wall)


def command_time(build, args, runs):
    """Median wall and CPU time of a whole `flexure` process, its exit code (of the last run)."""
    walls, cpus, rc = [], [], 0
    for _ in range(runs):
        wall, cpu, rc, _ = run_timed([os.path.join(build, "flexure")] + args)
        walls.append(wall)
        cpus.append(cpu)
    return statistics.median(walls), statistics.median(cpus), rc


def edges_table(build, baseline, runs, baseline_label=None):
    """Issue 27's commands, this build against --baseline (if given), one run of this script."""
    import tempfile
    report = run_program(build, "shooting_sweep_bench", 5, None, "BM_GslBrentReference")
    cpu, _, unit = medians(report)["BM_GslBrentReference"]
    reference = to_seconds(cpu, unit)
    builds = [("this build", build)] + ([("baseline", baseline)] if baseline else [])
    versions = {label: flexure_version(b) for label, b in builds}
    if baseline and baseline_label:
        versions["baseline"] = baseline_label
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for threads in (1, 2):
            cells = []
            for label, b in builds:
                cpu, wall = sweep_per_point(b, tmp, runs, threads)
                cells.append(f"{pretty(cpu)} CPU, {pretty(wall)} wall ({cpu / reference:.3g}x)"
                             if threads == 1 else f"{pretty(wall)} wall")
            rows.append((f"`flexure sweep beam --method shooting --n 0 --alpha2 0.5:10:500 "
                         f"--threads {threads}`, per point", cells))
        for n, alpha2, angle in GUIDED:
            args = ["beam", "--method", "chain", "--boundary", "guided", "--n", n, "--alpha2",
                    alpha2, "--tip-angle", angle, "--json"]
            cells = []
            for label, b in builds:
                # The baseline takes seconds per run: once.
                wall, cpu, rc = command_time(b, args, runs if label == "this build" else 1)
                cells.append(f"{pretty(wall)} wall, {pretty(cpu)} CPU, exit {rc}")
            rows.append((f"`flexure beam --method chain --boundary guided --n {n} --alpha2 "
                         f"{alpha2} --tip-angle {angle}`", cells))
        # The element count: a 0.1 ms difference, below the noise of a whole 4 ms process on a
        # shared machine, so the loads go through the Python module's vectorised flexure.beam (a
        # path a user runs, the same solve_beam) and its CPU time per load is taken.
        for elements in (10, 20, 30, 40):
            cells = []
            for label, b in builds:
                env = dict(os.environ, PYTHONPATH=os.path.join(b, "python"))
                times = [float(subprocess.run(
                    ["/usr/bin/python3", "-c", PYTHON_CHAIN, str(elements)], capture_output=True,
                    text=True, check=True, env=env).stdout) for _ in range(runs)]
                cells.append(f"{pretty(statistics.median(times))} CPU per load")
            rows.append((f"`flexure.beam(alpha2=numpy.full(400, 10.0), method=\"chain\", "
                         f"elements={elements}, threads=1)` (= `flexure beam --method chain "
                         f"--alpha2 10 --elements {elements}`)", cells))
    header = "| command | " + " | ".join(f"{label} ({versions[label]})" for label, _ in builds)
    lines = [f"Whole processes, medians of {runs} runs (the baseline's guided chain: one run; the "
             f"element counts: the CPU time per load of 400 loads in one call of the Python "
             f"module); CPU is the task clock of `perf stat`; "
             f"x = CPU per point / `BM_GslBrentReference` ({pretty(reference)}, "
             f"shooting_sweep_bench in the same run):", "",
             header + " |", "|---|" + "---|" * len(builds)]
    for command, cells in rows:
        lines.append(f"| {command} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def sweep_verdict_table(build, baseline, runs, baseline_label=None):
    """Issue 27's shooting sweep with the stability verdict (the default) and without it
    (--stability off), n = 0 (the issue's, a beam in tension) and n = 2 (compressed), this build
    against --baseline (if given), with the GSL + Brent yardstick of shooting_sweep_bench, one run
    of this script."""
    import tempfile
    report = run_program(build, "shooting_sweep_bench", 5, None, "BM_GslBrentReference")
    cpu, _, unit = medians(report)["BM_GslBrentReference"]
    reference = to_seconds(cpu, unit)
    builds = [("this build", build)] + ([("baseline", baseline)] if baseline else [])
    versions = {label: flexure_version(b) for label, b in builds}
    if baseline and baseline_label:
        versions["baseline"] = baseline_label
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in ("0", "2"):
            per_build = []
            for label, b in builds:
                on, _ = sweep_per_point(b, tmp, runs, 1, n)
                off, _ = sweep_per_point(b, tmp, runs, 1, n, ["--stability", "off"])
                per_build.append((on, off))
            command = (f"`flexure sweep beam --method shooting --n {n} --alpha2 0.5:10:500 "
                       f"--threads 1`")
            rows.append((f"{command}, per point, with the verdict (default)",
                         [f"{pretty(on)} CPU ({on / reference:.3g}x)" for on, _ in per_build]))
            rows.append((f"the same with `--stability off`",
                         [f"{pretty(off)} CPU ({off / reference:.3g}x)" for _, off in per_build]))
            rows.append(("the verdict's share (difference)",
                         [f"{pretty(max(on - off, 0.0))} CPU" for on, off in per_build]))
    header = "| command | " + " | ".join(f"{label} ({versions[label]})" for label, _ in builds)
    lines = [f"Whole processes, CPU per point = (CPU of the 500-point sweep - CPU of the 1-point "
             f"sweep) / 499 by the task clock of `perf stat`, medians of {runs} runs; "
             f"x = CPU per point / `BM_GslBrentReference` ({pretty(reference)}, "
             f"shooting_sweep_bench in the same run):", "",
             header + " |", "|---|" + "---|" * len(builds)]
    for command, cells in rows:
        lines.append(f"| {command} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


# Issue 31's shipped general mechanisms (docs/mechanisms.md "Shipped examples").
GENERAL_EXAMPLES = ["howell_bistable_switch", "parallel_guide", "double_parallelogram_stage",
                    "cross_axis_pivot", "inclined_bistable_beam",
                    "howell_partially_compliant_fourbar", "howell_fully_compliant_fourbar",
                    "howell_bicycle_brakes", "howell_compliant_gripper"]


def general_mechanisms_table(build, runs):
    """`flexure mechanism analyze FILE --model prbm|exact --json` of each shipped general
    mechanism: whole-process wall and CPU time (medians of `runs`), the points solved, the largest
    input load, the unloaded equilibria with their verdicts and the limit points, all read from
    the command's own JSON."""
    rows = []
    for name in GENERAL_EXAMPLES:
        path = os.path.join(ROOT, "docs", "examples", name + ".toml")
        for model in ("prbm", "exact"):
            args = ["mechanism", "analyze", path, "--model", model, "--json"]
            wall, cpu, rc = command_time(build, args, runs)
            _, _, _, out = run_timed([os.path.join(build, "flexure")] + args)
            d = json.loads(out)
            if rc:
                why = d.get("error", "").replace(ROOT + os.sep, "")
                rows.append((name, model, f"refused (exit {rc}): {why[:110]}...", "", "", "", ""))
                continue
            angle = d["input_unit"] == "rad"
            scale, unit = (180.0 / 3.141592653589793, "deg") if angle else (1e3, "mm")

            def at(x):  # a zero of a symmetric mechanism comes out at round-off: print 0
                return f"{x * scale if abs(x * scale) > 1e-9 else 0.0:.5g} {unit}"
            equilibria = ", ".join(f"{at(e['input'])} {e['stability']}"
                                   for e in d.get("equilibria", [])) or "none"
            limits = ", ".join(at(x["input"]) if isinstance(x, dict) else at(x)
                               for x in d.get("limit_points", [])) or "none"
            load = max(abs(v) for v in d["input_load"] if v is not None)
            rows.append((name, model, f"{pretty(wall)} wall, {pretty(cpu)} CPU",
                         str(len(d["input"])), f"{load:.4g} {d['input_load_unit']}", equilibria,
                         limits))
    lines = [f"Whole processes of `flexure mechanism analyze docs/examples/NAME.toml --model MODEL "
             f"--json` ({flexure_version(build)}), medians of {runs} runs; CPU is the task clock "
             f"of `perf stat`; the other columns are the command's JSON (inputs in deg for a "
             f"rotation, mm for a displacement):", "",
             "| mechanism | model | time | points | largest input load | unloaded equilibria "
             "| limit points |", "|---|---|---|---|---|---|---|"]
    for row in rows:
        lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--repetitions", type=int, default=5)
    parser.add_argument("--only", nargs="*", help="regenerate these tables only")
    parser.add_argument("--from-json", help="use the JSON files saved in this directory")
    parser.add_argument("--keep", help="save each program's JSON here")
    parser.add_argument("--startup-runs", type=int, default=41)
    parser.add_argument("--python-runs", type=int, default=5)
    parser.add_argument("--baseline", help="an older build directory: the before column of the "
                        "edges table")
    parser.add_argument("--baseline-label", help="how the edges table names the baseline (default: "
                        "its `flexure --version` commit)")
    parser.add_argument("--edge-runs", type=int, default=5)
    args = parser.parse_args()
    def render(name):
        if args.only and name not in args.only:
            return None
        if name == "startup":
            table = startup_table(args.build, args.startup_runs)
        elif name == "python_beam":
            table = python_beam_table(args.build, args.python_runs)
        elif name == "python_scalar":
            table = python_scalar_table(args.build, args.repetitions)
        elif name == "sweep_verdict":
            table = sweep_verdict_table(args.build, args.baseline, args.edge_runs,
                                        args.baseline_label)
        elif name == "general_mechanisms":
            table = general_mechanisms_table(args.build, args.edge_runs)
        elif name == "edges":
            table = edges_table(args.build, args.baseline, args.edge_runs, args.baseline_label)
        elif args.from_json:
            with open(os.path.join(args.from_json, name + ".json"), encoding="utf-8") as f:
                table = benchmark_table(name, json.load(f))
        else:
            table = benchmark_table(name, run_program(args.build, name, args.repetitions,
                                                      args.keep))
        print(f"perf_tables.py: {name}", file=sys.stderr)
        return table

    rewrite_blocks(DOC, "perf-table", render)
    print(f"wrote {DOC}")


if __name__ == "__main__":
    main()
