#!/usr/bin/env python3
"""What sets the axial bar's error floor: amplitude, time-step and
resolution studies (tutorials/mpm/axialBar: CBS, consistent mass, FLIP
alpha 1, 2 points per cell, fixed time step, t = 0 .. 50 = 5 periods).

    $MPMFOAM_PYTHON benchmarks/accuracyCost/floorStudy.py [--jobs 2]

1. Amplitude: V0 = 0.1, 0.01, 0.001, 1e-4, 1e-6 at 100 bar cells and
   dt = 0.005 (CFL 0.2), and V0 = 0.1, 1e-6 at 200 cells, dt = 0.0025. The reference (2 V0/pi) cos(w1 t) is the linear small-strain
   solution; the solver is updated Lagrangian (finite strain, in 1D
   sigma = E ln(stretch)), so a part of the error that scales with V0 is the
   reference's, not the scheme's.
2. Time step at fixed resolution (100 cells, V0 = 1e-6): dt = 0.02 ... 0.000625.
   Error against the exact solution and, to isolate the time integration,
   against the finest-dt run of the same grid (the semi-discrete solution);
   observed order = log2 of successive ratios. Also the error against the
   exact solution evaluated half a step earlier (t - dt/2): the explicit
   velocities are leapfrog half-step values.
3. Resolution at a small step (CFL 0.05, V0 = 1e-6): 25, 50, 100, 200 cells.

Prints three tables; every number is from these runs.
"""
import argparse
import concurrent.futures as cf
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import run as bar  # noqa: E402  (setup helpers of the sweep)

L, C = bar.L, bar.C
W1 = bar.W1
END = 50.0


def run_case(scratch, tag, cells, dt, v0, mass="consistent", shape="CBS", ppc=2, alpha=1.0):
    case = os.path.join(scratch, tag)
    shutil.copytree(bar.TUTORIAL, case, ignore=shutil.ignore_patterns("*.png", "log.*"))
    steps = int(round(END/dt))
    bar.sub(f"{case}/system/blockMeshDict", r"^nCells .*", f"nCells  {cells*6//5};")
    bar.sub(f"{case}/system/controlDict", r"^deltaT .*", f"deltaT          {END/steps!r};")
    bar.sub(f"{case}/system/controlDict", r"^endTime .*", f"endTime         {END:g};")
    bar.sub(f"{case}/system/controlDict", r"^writeInterval .*", f"writeInterval   {END:g};")
    bar.sub(f"{case}/system/mpmSetParticlesDict", r"pointsPerCell +\d+;", f"pointsPerCell {ppc};")
    bar.sub(f"{case}/system/mpmSetParticlesDict", r"amplitude +\([^)]*\);", f"amplitude  ({v0!r} 0 0);")
    p = f"{case}/constant/mpmProperties"
    bar.sub(p, r"^shapeFunction .*", f"shapeFunction   {bar.SHAPES[shape]};")
    bar.sub(p, r"^flipRatio .*", f"flipRatio       {alpha:g};")
    bar.sub(p, r"^massMatrix .*", f"massMatrix      {mass};")
    bar.sub(p, r"^logInterval .*", f"logInterval     {max(1, steps//2000)};")
    bar.sub(p, r"type +adaptive;", "type        fixed;")
    env = dict(os.environ, OMP_NUM_THREADS="1")
    for app in ("blockMesh", "mpmSetParticles", "mpmFoam"):
        with open(f"{case}/log.{app}", "w") as lf:
            if subprocess.run([app], cwd=case, stdout=lf, stderr=subprocess.STDOUT, env=env).returncode:
                raise RuntimeError(f"{app} failed in {case}")
    s = bar.mpmPost.read_summary(case)
    t, v = s["time"], s["Ux"]
    amp = 2*v0/math.pi
    log = open(f"{case}/log.mpmFoam").read()
    cost = sum(bar.cost_breakdown(log).values())
    shutil.rmtree(case, ignore_errors=True)
    return dict(tag=tag, cells=cells, dt=END/steps, v0=v0, t=t, v=v/amp,
                err=np.max(np.abs(v/amp - np.cos(W1*t))),
                errHalf=np.max(np.abs(v/amp - np.cos(W1*(t - 0.5*END/steps)))),
                cost=cost)


def orders(errs):
    return ["" if i == 0 or not (errs[i - 1] > 0 and errs[i] > 0) else f"{math.log2(errs[i - 1]/errs[i]):.2f}"
            for i in range(len(errs))]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    scratch = tempfile.mkdtemp(prefix="barFloor.")
    print("Machine:", "; ".join(bar.machine_info()[1:4]))
    amps = [0.1, 0.01, 1e-3, 1e-4, 1e-6]
    dts = [0.02, 0.01, 0.005, 0.0025, 0.00125, 0.000625]
    cells = [25, 50, 100, 200]
    jobs = [("amp", a, dict(cells=100, dt=0.005, v0=a)) for a in amps]
    jobs += [("amp200", a, dict(cells=200, dt=0.0025, v0=a)) for a in (0.1, 1e-6)]
    jobs += [("dt", d, dict(cells=100, dt=d, v0=1e-6)) for d in dts]
    jobs += [("h", n, dict(cells=n, dt=0.05*(L/n)/C, v0=1e-6)) for n in cells]
    jobs += [("hL", n, dict(cells=n, dt=0.05*(L/n)/C, v0=1e-6, mass="lumped")) for n in cells]
    t0 = time.perf_counter()
    res = {}
    with cf.ThreadPoolExecutor(args.jobs) as pool:
        futs = {pool.submit(run_case, scratch, f"{k}_{x}", **kw): (k, x) for k, x, kw in jobs}
        for f in cf.as_completed(futs):
            res[futs[f]] = f.result()
    shutil.rmtree(scratch, ignore_errors=True)
    print(f"{len(jobs)} runs in {time.perf_counter() - t0:.1f} s\n")

    print("1. Amplitude (CBS consistent, 2 ppc, 100 cells, dt = 0.005, CFL 0.2)")
    print(f"   {'V0':>8s} {'strain amp':>10s} {'vs exact':>12s} {'time-centred':>12s} {'vs V0=1e-6 run':>15s}")
    small = res[("amp", 1e-6)]
    for a in amps:
        r = res[("amp", a)]
        d = np.max(np.abs(r["v"] - small["v"]))
        print(f"   {a:8.0e} {a/C:10.1e} {r['err']:12.3e} {r['errHalf']:12.3e} {d:15.3e}")
    print("   same at 200 cells, dt = 0.0025 (CFL 0.2):")
    small = res[("amp200", 1e-6)]
    for a in (0.1, 1e-6):
        r = res[("amp200", a)]
        d = np.max(np.abs(r["v"] - small["v"]))
        print(f"   {a:8.0e} {a/C:10.1e} {r['err']:12.3e} {r['errHalf']:12.3e} {d:15.3e}")

    print("\n2. Time step at fixed resolution (100 cells, V0 = 1e-6)")
    fine = res[("dt", dts[-1])]
    e = [res[("dt", d)]["err"] for d in dts]
    eh = [res[("dt", d)]["errHalf"] for d in dts]
    # Time integration alone: each run's half-step values against the finest
    # run of the same grid at the same instants (t - dt/2), so the spatial
    # error cancels and the output lag is taken out.
    # The centred error signals are small and smooth, so interpolating the
    # finest run's signal to another run's sample times costs nothing.
    dtf = fine["dt"]
    df = fine["v"] - np.cos(W1*(fine["t"] - 0.5*dtf))
    et = [np.max(np.abs(res[("dt", d)]["v"] - np.cos(W1*(res[("dt", d)]["t"] - 0.5*d))
                        - np.interp(res[("dt", d)]["t"], fine["t"], df)))
          for d in dts[:-1]]
    ok = [e_ < 1 for e_ in e]
    oe = orders([x if k else math.nan for x, k in zip(e, ok)])
    ot = orders([x if k else math.nan for x, k in zip(et, ok)])
    print("   ('vs exact': max |v_cm(t) - exact(t)|; 'time-centred': against exact(t - dt/2);")
    print("    'time integration alone': time-centred against the finest-dt run, same grid)")
    print(f"   {'dt':>8s} {'CFL':>5s} {'vs exact':>10s} {'order':>6s} {'w1 dt/2':>9s} {'time-centred':>12s} "
          f"{'time integ.':>11s} {'order':>6s} {'time s':>7s}")
    for i, d in enumerate(dts):
        tt = f"{et[i]:11.3e} {ot[i]:>6s}" if i < len(et) else f"{'(ref)':>11s} {'':6s}"
        note = "" if ok[i] else "  unstable"
        print(f"   {d:8.5f} {C*d/(L/100):5.2f} {e[i]:10.3e} {oe[i]:>6s} {W1*d/2:9.3e} {eh[i]:12.3e} {tt} "
              f"{res[('dt', d)]['cost']:7.2f}{note}")

    for key, name in (("h", "consistent"), ("hL", "lumped")):
        print(f"\n3. Resolution, CBS {name} mass, 2 ppc, CFL 0.05, V0 = 1e-6")
        e = [res[(key, n)]["err"] for n in cells]
        eh = [res[(key, n)]["errHalf"] for n in cells]
        o, oh = orders(e), orders(eh)
        print(f"   {'cells':>6s} {'dt':>9s} {'vs exact':>10s} {'order':>6s} {'vs exact(t-dt/2)':>17s} "
              f"{'order':>6s} {'time s':>7s}")
        for i, n in enumerate(cells):
            r = res[(key, n)]
            print(f"   {n:6d} {r['dt']:9.2e} {e[i]:10.3e} {o[i]:>6s} {eh[i]:17.3e} {oh[i]:>6s} {r['cost']:7.2f}")


if __name__ == "__main__":
    main()
