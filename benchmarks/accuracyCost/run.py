#!/usr/bin/env python3
"""What accuracy costs: the axial bar (tutorials/mpm/axialBar) swept over
shape function, FLIP fraction, points per cell, cells, CFL and mass matrix.

For every run: the max centre-of-mass velocity error over 5 periods
(relative to the amplitude 2 V0/pi), the mass-weighted RMS error of the
point velocities at t = 50 against V0 sin(pi x/2L) cos(w1 t) (relative to
V0), and the cost (the solver's own timers from its "Cost breakdown", the
wall clock of the mpmFoam process, steps, points).

The time step is fixed (timeStep { type fixed; }) at CFL = fraction x the
analysed USL stability limit of mpmStabilityAnalysis --limit for the
shape/alpha/lattice offsets (lumped mass). Consistent-mass runs (2 Jacobi
sweeps) use the lumped limit / sqrt(1 + 2) as their basis.

Usage (from anywhere, after `source etc/bashrc`):
    $MPMFOAM_PYTHON benchmarks/accuracyCost/run.py            # full sweep
    $MPMFOAM_PYTHON benchmarks/accuracyCost/run.py --quick    # smoke check
Options: --jobs N (default 2), --outdir DIR (default: this folder; --quick
writes to a new /tmp/accuracyCostQuick.* folder unless --outdir is given), --keep (keep cases),
--no-probe (skip the 1.1 x limit probes), --plot-only (redraw the PNG
from results.csv).
"""
import argparse
import concurrent.futures as cf
import csv
import datetime
import itertools
import math
import os
import platform
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import accuracyCostLib as lib  # noqa: E402

ROOT = os.environ.get("MPMFOAM_DIR", os.path.abspath(os.path.join(HERE, "..", "..")))
sys.path.insert(0, os.path.join(ROOT, "etc", "python"))
import mpmPost  # noqa: E402

TUTORIAL = os.path.join(ROOT, "tutorials", "mpm", "axialBar")
TOOL = os.path.join(ROOT, "build", "applications", "tools", "mpmStabilityAnalysis",
                    "mpmStabilityAnalysis")

L, E, RHO = 25.0, 100.0, 1.0
# Small amplitude (strain amplitude V0/c = 1e-7): the solver is finite-strain
# (updated Lagrangian, in 1D sigma = E ln(stretch)) while the reference is the
# linear solution; at the tutorial's V0 = 0.1 (strain 1e-2) that difference,
# 3.6e-3 of the v_cm amplitude, was the sweep's floor (floorStudy.py).
V0 = 1e-6
C = math.sqrt(E/RHO)
W1 = math.pi/(2*L)*C
END_TIME = 50.0          # 5 periods of the first mode
MESH_LENGTH = 30.0       # 25 of bar + 5 of buffer, nCells = 6/5 n
SWEEPS = 2               # consistentMassIterations (solver default)
SAMPLES = 1000           # ~ rows of summary.dat per run

SHAPES = {"LH": "linearHat", "QBS": "quadraticBSpline", "CBS": "cubicBSpline"}
# Lattice offsets of the seeded points: nodes sit at FV cell centres, points
# at (i + 0.5)/n of a cell, so the lattice offsets are those shifted by 0.5.
OFFSETS = {1: "0", 2: "0.25,0.75", 4: "0.125,0.375,0.625,0.875"}


def machine_info():
    cpu = "unknown"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    load = " ".join(f"{x:.2f}" for x in os.getloadavg())
    try:
        commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                                capture_output=True, text=True).stdout.strip()
    except OSError:
        commit = "?"
    return [
        f"date: {datetime.datetime.now().isoformat(timespec='seconds')}",
        f"cpu: {cpu}",
        f"cores: {os.cpu_count()}",
        f"load average (1, 5, 15 min) at start: {load}",
        f"system: {platform.system()} {platform.release()} {platform.machine()}",
        f"mpmFoam commit: {commit}",
    ]


def analysed_limits():
    """{(shape, alpha, mass, ppc): CFL limit} from mpmStabilityAnalysis."""
    lim = {}
    tmp = tempfile.mkdtemp(prefix="accuracyCostLimits.")
    try:
        for ppc, off in OFFSETS.items():
            f = os.path.join(tmp, f"limits{ppc}.csv")
            subprocess.run([TOOL, "--model", "wave", "--scheme", "USL",
                            "--shape", "LH,QBS,CBS", "--alpha", "0,0.95,1",
                            "--mass", "lumped,consistent", "--offsets", off,
                            "--limit", "--limit-csv", f],
                           check=True, capture_output=True, text=True)
            with open(f) as fh:
                for r in csv.DictReader(fh):
                    lim[(r["shape"], float(r["alpha"]), r["mass"], ppc)] = float(r["limit"])
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return lim


def make_runs(quick, probe, limits):
    runs = []

    def add(kind, shape, alpha, mass, ppc, cells, frac):
        lumped = limits[(shape, alpha, "lumped", ppc)]
        basis = lumped if mass == "lumped" else lumped/math.sqrt(1 + SWEEPS)
        runs.append(dict(set=kind, shape=shape, alpha=alpha, mass=mass, ppc=ppc,
                         cells=cells, cflFraction=frac, limitBasis=basis,
                         analysedLimitConsistent=limits[(shape, alpha, "consistent", ppc)]))

    if quick:
        for shape, cells, frac in itertools.product(["LH", "CBS"], [25, 50], [0.5, 0.9]):
            add("grid", shape, 1.0, "lumped", 2, cells, frac)
        add("consistent", "CBS", 1.0, "consistent", 2, 25, 0.9)
        if probe:
            add("probe", "LH", 1.0, "lumped", 1, 25, 1.5)   # must blow up
        return runs
    shapes, alphas, ppcs = ["LH", "QBS", "CBS"], [0.0, 0.95, 1.0], [1, 2, 4]
    cells, fracs = [25, 50, 100, 200], [0.1, 0.5, 0.9]
    for s, a, p, n, f in itertools.product(shapes, alphas, ppcs, cells, fracs):
        add("grid", s, a, "lumped", p, n, f)
    for a, p, n, f in itertools.product(alphas, ppcs, cells, fracs):
        add("consistent", "CBS", a, "consistent", p, n, f)
    if probe:
        # Just beyond the analysed limit: does the bar blow up where the
        # periodic analysis says it must? (not used for the front)
        for s, a, p in itertools.product(shapes, alphas, ppcs):
            add("probe", s, a, "lumped", p, 50, 1.1)
    return runs


def sub(path, pattern, repl):
    with open(path) as f:
        text = f.read()
    text, n = re.subn(pattern, repl, text, flags=re.M)
    if n == 0:
        raise RuntimeError(f"{path}: no match for {pattern!r}")
    with open(path, "w") as f:
        f.write(text)


def setup_case(case, r):
    shutil.copytree(TUTORIAL, case, ignore=shutil.ignore_patterns("*.png", "log.*"))
    n = r["cells"]
    h = L/n
    steps = math.ceil(END_TIME*C/(r["cflFraction"]*r["limitBasis"]*h) - 1e-9)
    dt = END_TIME/steps
    r.update(steps=steps, dt=dt, cfl=C*dt/h, points=n*r["ppc"])
    # Does a point cross a lattice node (FV cell centre) while it oscillates
    # with the displacement amplitude (V0/w1) sin(pi x/2L)? The frozen-point
    # stability analysis cannot see what happens then.
    xp = (np.arange(n*r["ppc"]) + 0.5)*h/r["ppc"]
    dist = np.abs((xp/h - 0.5) - np.round(xp/h - 0.5))*h
    r["nodeCrossing"] = int(np.any(dist < V0/W1*np.sin(math.pi*xp/(2*L)) - 1e-12))
    sub(f"{case}/system/blockMeshDict", r"^nCells .*", f"nCells  {n*6//5};")
    sub(f"{case}/system/blockMeshDict", r"^length .*", f"length  {MESH_LENGTH:g};")
    sub(f"{case}/system/controlDict", r"^deltaT .*", f"deltaT          {dt!r};")
    sub(f"{case}/system/controlDict", r"^endTime .*", f"endTime         {END_TIME:g};")
    sub(f"{case}/system/controlDict", r"^writeInterval .*", f"writeInterval   {END_TIME:g};")
    sub(f"{case}/system/mpmSetParticlesDict", r"pointsPerCell +\d+;", f"pointsPerCell {r['ppc']};")
    sub(f"{case}/system/mpmSetParticlesDict", r"amplitude +\([^)]*\);", f"amplitude  ({V0!r} 0 0);")
    p = f"{case}/constant/mpmProperties"
    sub(p, r"^shapeFunction .*", f"shapeFunction   {SHAPES[r['shape']]};")
    sub(p, r"^flipRatio .*", f"flipRatio       {r['alpha']:g};")
    sub(p, r"^massMatrix .*", f"massMatrix      {r['mass']};\nconsistentMassIterations {SWEEPS};")
    sub(p, r"^logInterval .*", f"logInterval     {max(1, steps//SAMPLES)};")
    sub(p, r"type +adaptive;", "type        fixed;")


def cost_breakdown(log):
    keys = {"P2G": "p2gTime", "nodal update": "nodalTime", "G2P": "g2pTime",
            "constitutive": "constitutiveTime", "I/O": "ioTime"}
    out = {}
    for name, key in keys.items():
        m = re.search(r"^\s*" + re.escape(name) + r"\s+([-+0-9.eE]+) s", log, re.M)
        if m:
            out[key] = float(m.group(1))
    return out


def errors(case, dt):
    s = mpmPost.read_summary(case)
    t, v = s["time"], s["Ux"]
    amp = 2*V0/math.pi
    e = np.abs(v - amp*np.cos(W1*t))/amp
    # The explicit velocities are leapfrog half-step values: against the
    # exact solution half a step earlier the O(w dt/2) lag drops out.
    ec = np.abs(v - amp*np.cos(W1*(t - 0.5*dt)))/amp
    tname = mpmPost.times(case)[-1]
    tf = float(tname)
    x = mpmPost.read_positions(case, tname)[:, 0]
    u = np.atleast_2d(mpmPost.read_cloud_field(case, tname, "U"))[:, 0]
    m = np.broadcast_to(mpmPost.read_cloud_field(case, tname, "mass"), x.shape)
    ex = V0*np.sin(math.pi*x/(2*L))*math.cos(W1*tf)
    l2 = math.sqrt(np.sum(m*(u - ex)**2)/np.sum(m))/V0
    if abs(tf - END_TIME) > 1e-6:
        raise RuntimeError(f"last time {tname} != {END_TIME}")
    return e.max(), math.sqrt(np.mean(e**2)), l2, ec.max()


def run_one(r, scratch, idx):
    case = os.path.join(scratch, f"run{idx:04d}")
    setup_case(case, r)
    env = dict(os.environ, OMP_NUM_THREADS="1")
    r.update(status="failed", failure="", maxURatio=math.nan, vcmMaxError=math.nan, vcmRmsError=math.nan, L2Error=math.nan, vcmCentredError=math.nan,
             solverTime=math.nan, wallTime=math.nan, secPerPointStep=math.nan)
    for app in ("blockMesh", "mpmSetParticles"):
        with open(f"{case}/log.{app}", "w") as lf:
            if subprocess.run([app], cwd=case, stdout=lf, stderr=subprocess.STDOUT, env=env).returncode:
                return r
    t0 = time.perf_counter()
    with open(f"{case}/log.mpmFoam", "w") as lf:
        rc = subprocess.run(["mpmFoam"], cwd=case, stdout=lf, stderr=subprocess.STDOUT, env=env).returncode
    r["wallTime"] = time.perf_counter() - t0
    with open(f"{case}/log.mpmFoam") as lf:
        log = lf.read()
    cb = cost_breakdown(log)
    r.update(cb)
    if len(cb) == 5:
        r["solverTime"] = sum(cb.values())
        r["secPerPointStep"] = r["solverTime"]/(r["points"]*r["steps"])
    if rc != 0:
        # every stop of the solver on a blown-up state (non-finite values,
        # points compressed to J <= 0) starts "Stopping at time t"
        m = re.search(r"Stopping at time ([^:, ]+)[:,] (.*)", log)
        if m:
            r["status"] = "unstable"
            step = re.search(r"at step (\d+)|step (\d+):", m.group(2))
            what = "J <= 0" if "compressed to zero volume" in m.group(2) else "non-finite"
            r["failure"] = (f"{what} at step {next(g for g in step.groups() if g)} " if step else f"{what} ") \
                + f"(t = {float(m.group(1)):.4g})"
        else:
            r["log"] = log[-2000:]
        return r
    try:
        vmax, vrms, l2, vc = errors(case, r["dt"])
    except Exception as exc:  # noqa: BLE001 - reported as a failed run
        r["log"] = f"post-processing: {exc}"
        return r
    r.update(vcmMaxError=vmax, vcmRmsError=vrms, L2Error=l2, vcmCentredError=vc)
    r["maxURatio"] = float(np.max(mpmPost.read_summary(case)["maxU"]))/V0
    finite = all(math.isfinite(x) for x in (vmax, vrms, l2))
    r["status"] = "ok" if finite and vmax <= 1 and l2 <= 1 else "unstable"
    if r["status"] == "unstable":
        grow = "growing" if not r["maxURatio"] <= 2 else "bounded"
        r["failure"] = f"error > 1, {grow} (max |U| = {r['maxURatio']:.3g} V0)"
    return r


def write_csv(path, machine, rows):
    with open(path, "w", newline="") as f:
        for line in machine:
            f.write(f"# {line}\n")
        w = csv.DictWriter(f, fieldnames=lib.COLUMNS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})


COLOURS = {"LH": "tab:blue", "QBS": "tab:orange", "CBS": "tab:green"}


def plot(path, rows, machine_short):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    good = [r for r in rows if lib.usable(r)]
    front = lib.pareto(good, "vcmMaxError", "solverTime")
    fig = plt.figure(figsize=(13, 6.5))
    ax = fig.add_axes([0.07, 0.09, 0.55, 0.8])
    for s, col in COLOURS.items():
        for mass, mk in (("lumped", "o"), ("consistent", "s")):
            pts = [r for r in good if r["shape"] == s and r["mass"] == mass]
            if pts:
                ax.scatter([r["solverTime"] for r in pts], [r["vcmMaxError"] for r in pts],
                           s=14, c=col, alpha=0.3, marker=mk, linewidths=0,
                           label=f"{s} {mass} ({len(pts)})")
    ax.plot([r["solverTime"] for r in front], [r["vcmMaxError"] for r in front],
            "k-", lw=1, zorder=3)
    key = ["Pareto front (error, time s, configuration;",
           "aX = alpha, lump/cons = mass, nN = bar cells,",
           "F L = CFL fraction of the analysed limit):"]
    for i, r in enumerate(front, 1):
        ax.scatter([r["solverTime"]], [r["vcmMaxError"]], s=46, c=COLOURS[r["shape"]],
                   marker="s" if r["mass"] == "consistent" else "o",
                   edgecolors="k", linewidths=1.2, zorder=4)
        ax.annotate(str(i), (r["solverTime"], r["vcmMaxError"]),
                    xytext=(5, 3 if i % 2 else -9), textcoords="offset points", fontsize=7)
        key.append(f"{i:2d}  {r['vcmMaxError']:.2e}  {r['solverTime']:7.3f}  {lib.label(r, short=True)}")
    fig.text(0.64, 0.89, "\n".join(key), va="top", ha="left", family="monospace", fontsize=7.5)
    bad = sum(1 for r in rows if r["status"] != "ok" and r["set"] != "probe")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("mpmFoam time (s, solver cost breakdown total)")
    ax.set_ylabel("max |v_cm - exact| / (2 V0/pi) over 5 periods")
    fig.suptitle(f"Axial bar: accuracy vs cost, {len(good)} stable runs "
                 f"({bad} unstable/failed not shown), Pareto front in black\n{machine_short}",
                 fontsize=10)
    ax.grid(True, which="both", alpha=0.25)
    ax.legend(fontsize=8, loc="lower left")
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="small subset (< 1 min)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--outdir", default=None)
    ap.add_argument("--keep", action="store_true", help="keep the scratch cases")
    ap.add_argument("--no-probe", dest="probe", action="store_false")
    ap.add_argument("--plot-only", action="store_true",
                    help="redraw accuracyCost.png from OUTDIR/results.csv, no runs")
    args = ap.parse_args()
    if args.plot_only:
        outdir = args.outdir or HERE
        header, rows = lib.read_results(os.path.join(outdir, "results.csv"))
        m = [h[2:].strip() for h in header]
        plot(os.path.join(outdir, "accuracyCost.png"), rows,
             f"{m[1]}, {m[2]}; {m[-1]}")
        print(f"wrote {os.path.join(outdir, 'accuracyCost.png')}")
        return

    machine = machine_info()
    machine.append(f"jobs: {args.jobs} mpmFoam processes at a time, OMP_NUM_THREADS=1")
    print("Machine:")
    for line in machine:
        print("  " + line)
    sys.stdout.flush()
    for exe in ("blockMesh", "mpmSetParticles", "mpmFoam"):
        if shutil.which(exe) is None:
            sys.exit(f"{exe} not on PATH: source etc/bashrc first")
    if not os.access(TOOL, os.X_OK):
        sys.exit(f"{TOOL} missing: build it (cmake --build build --target mpmStabilityAnalysis)")

    limits = analysed_limits()
    runs = make_runs(args.quick, args.probe, limits)
    # Random (seeded) order: a change of machine load hits configurations at
    # random rather than all the runs of one shape function.
    order = list(range(len(runs)))
    random.Random(1912).shuffle(order)
    scratch = tempfile.mkdtemp(prefix="accuracyCost.")
    outdir = args.outdir or (tempfile.mkdtemp(prefix="accuracyCostQuick.") if args.quick else HERE)
    os.makedirs(outdir, exist_ok=True)
    print(f"{len(runs)} runs in {scratch}, {args.jobs} at a time; results -> {outdir}")
    sys.stdout.flush()

    t0 = time.perf_counter()
    done = 0
    with cf.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futs = {pool.submit(run_one, runs[i], scratch, i): i for i in order}
        for fut in cf.as_completed(futs):
            r = fut.result()
            done += 1
            if not args.keep and r["status"] != "failed":
                shutil.rmtree(os.path.join(scratch, f"run{futs[fut]:04d}"), ignore_errors=True)
            if r["status"] != "ok" or done % 25 == 0 or args.quick:
                print(f"[{done:4d}/{len(runs)} {time.perf_counter() - t0:7.1f} s] "
                      f"{r['status']:8s} {lib.label(r, short=True):32s} "
                      f"vcm {r['vcmMaxError']:.3e} L2 {r['L2Error']:.3e} "
                      f"t {r['solverTime']:.3f} s")
                if r["status"] == "failed":
                    print(r.get("log", "")[-800:])
                sys.stdout.flush()
    elapsed = time.perf_counter() - t0
    machine.append(f"load average (1, 5, 15 min) at end: "
                   + " ".join(f"{x:.2f}" for x in os.getloadavg()))
    machine.append(f"sweep wall time: {elapsed:.1f} s for {len(runs)} runs")

    csv_path = os.path.join(outdir, "results.csv")
    write_csv(csv_path, machine, runs)
    with open(os.path.join(outdir, "machine.txt"), "w") as f:
        f.write("\n".join(machine) + "\n")
    png = os.path.join(outdir, "accuracyCost.png")
    plot(png, runs, f"{machine[1]}, {machine[2]}; {machine[-1]}")

    counts = {}
    for r in runs:
        counts[(r["set"], r["status"])] = counts.get((r["set"], r["status"]), 0) + 1
    print(f"\nSweep wall time {elapsed:.1f} s. Status counts: "
          + ", ".join(f"{k[0]}/{k[1]} {v}" for k, v in sorted(counts.items())))
    bad = [r for r in runs if r["status"] != "ok"]
    for r in sorted(bad, key=lambda r: (r["set"], r["shape"], r["alpha"], r["ppc"], r["cells"])):
        print(f"  {r['status']:8s} [{r['set']}] {lib.label(r)}; crossing {r['nodeCrossing']}: {r['failure']}")
    front = lib.pareto([r for r in runs if lib.usable(r)], "vcmMaxError", "solverTime")
    print("\nPareto front (max v_cm error vs solver time):")
    print(f"  {'vcm error':>10s} {'L2 error':>10s} {'time s':>8s} {'wall s':>7s} {'steps':>6s}  configuration")
    for r in front:
        print(f"  {r['vcmMaxError']:10.3e} {r['L2Error']:10.3e} {r['solverTime']:8.3f} "
              f"{r['wallTime']:7.2f} {r['steps']:6d}  {lib.label(r)}")
    print(f"\nwrote {csv_path}, {png}, {os.path.join(outdir, 'machine.txt')}")
    if any(r["status"] == "failed" for r in runs):
        print(f"some runs failed (not a blow-up): cases kept in {scratch}")
    elif not args.keep:
        shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    main()
