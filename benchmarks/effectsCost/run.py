#!/usr/bin/env python3
"""What each effect costs, in one run on one scene.

The scene is benchmarks/mppicComparison/mpmCase (a fluidised bed: 12 800
material points, 4 800 cells, druckerPrager grains with E = 1e7, so about 21
MPM sub-steps per fluid step). Each variant adds one effect to the one above
it (the diagnostics each to "+ virtual mass"):

  pure MPM            no fluid (no transportProperties), gravity, diagnostics ()
  + fluid, one-way    mode oneWay, forces (drag gravity)
  + two-way drag      mode twoWayMomentum
  + volume fraction   mode twoWay
  + pressure gradient forces (drag pressureGradient gravity)
  + virtual mass      forces (... virtualMass)
  + diagnostic X      diagnostics (X), for each diagnostic

Cost: the wall seconds of the time loop, summed from the solver's own
end-of-run cost breakdown (the MPM phases, I/O, the fluid, each force, the
coupling exchange, each diagnostic: everything the loop does but print the
per-step log lines of OpenFOAM itself), per fluid step, on one core
(OMP_NUM_THREADS=1); the median over the rounds. The variants run in turn
within each round, in flipped order every other round, so a slow spell of
the machine hits all of them. Increments are percentages of the variant each
one adds to; "spread" is (max - min)/median over the rounds.

Build switch: build/benchmarks/particleThroughputNoCoupling is
particleThroughput with the MPM step compiled without its fluid-coupling
terms (MPM_NO_FLUID_COUPLING). Both run in turn; the ratio of their point
throughput shows what the coupling hooks cost a pure-MPM step.

Usage (after `source etc/bashrc`):
    benchmarks/effectsCost/run.sh [--steps 40] [--rounds 3] [--keep]
"""
import argparse
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.environ.get("MPMFOAM_DIR", os.path.abspath(os.path.join(HERE, "..", "..")))
SCENE = os.path.join(ROOT, "benchmarks", "mppicComparison", "mpmCase")
BUILD = os.environ.get("MPMFOAM_BUILD", os.path.join(ROOT, "build"))

FORCES = "coupling/forces"
# name: (base variant, {mpmProperties entry: value}); None: remove
VARIANTS = [
    ("pure MPM", None, {}),
    ("+ fluid, one-way", "pure MPM", {"coupling/mode": "oneWay", FORCES: "(drag gravity)"}),
    ("+ two-way drag", "+ fluid, one-way", {"coupling/mode": "twoWayMomentum"}),
    ("+ volume fraction", "+ two-way drag", {"coupling/mode": "twoWay"}),
    ("+ pressure gradient", "+ volume fraction", {FORCES: "(drag pressureGradient gravity)"}),
    ("+ virtual mass", "+ pressure gradient", {FORCES: "(drag pressureGradient gravity virtualMass)"}),
    ("+ diagnostic summary", "+ virtual mass", {"diagnostics": "(summary)"}),
    ("+ diagnostic materialTotals", "+ virtual mass", {"diagnostics": "(materialTotals)"}),
]


def sh(cmd, cwd, log):
    with open(os.path.join(cwd, log), "w") as f:
        r = subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT)
    if r.returncode != 0:
        sys.exit(f"run.py: {' '.join(cmd)} failed in {cwd} (see {log})")


def machine():
    cpu = "?"
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            cpu = line.split(":", 1)[1].strip()
            break
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    return f"{cpu}, {os.cpu_count()} cores, {platform.system()} {platform.release()}, commit {commit}"


def settings(name):
    """Every mpmProperties edit of a variant, its bases' first."""
    by = {v[0]: v for v in VARIANTS}
    chain = []
    while name:
        chain.append(by[name])
        name = by[name][1]
    edits = {"diagnostics": "()"}
    for _, _, e in reversed(chain):
        edits.update(e)
    return edits


def prepare(tmp, steps):
    base = os.path.join(tmp, "base")
    shutil.copytree(SCENE, base)
    dt = float(re.search(r"^deltaT\s+([0-9.eE+-]+)", open(os.path.join(base, "system", "controlDict")).read(), re.M).group(1))
    sh(["foamDictionary", "-entry", "endTime", "-set", f"{steps*dt:.10g}", "system/controlDict"], base, "log.foamDictionary")
    sh(["foamDictionary", "-entry", "writeInterval", "-set", "1e6", "system/controlDict"], base, "log.foamDictionary")
    sh(["blockMesh"], base, "log.blockMesh")
    sh(["mpmSetParticles"], base, "log.mpmSetParticles")
    return base, dt


def make_case(base, tmp, i, name):
    case = os.path.join(tmp, f"v{i}")
    if not os.path.isdir(case):
        shutil.copytree(base, case)
        props = "constant/mpmProperties"
        sh(["foamDictionary", "-entry", "diagnostics", "-add", "()", props], case, "log.foamDictionary")
        for entry, value in settings(name).items():
            sh(["foamDictionary", "-entry", entry, "-set", value, props], case, "log.foamDictionary")
        if name == "pure MPM":
            sh(["foamDictionary", "-entry", "coupling", "-remove", props], case, "log.foamDictionary")
            for f in ("constant/transportProperties", "constant/turbulenceProperties", "0/U", "0/p"):
                os.remove(os.path.join(case, f))
    return case


def run_case(case, steps):
    """Seconds of the time loop per fluid step, and the log."""
    for d in os.listdir(case):
        if re.fullmatch(r"[0-9.eE+-]+", d) and float(d) > 0:
            shutil.rmtree(os.path.join(case, d))
    env = dict(os.environ, OMP_NUM_THREADS="1")
    with open(os.path.join(case, "log.mpmFoam"), "w") as log:
        r = subprocess.run(["mpmFoam"], cwd=case, env=env, stdout=log, stderr=subprocess.STDOUT)
    text = open(os.path.join(case, "log.mpmFoam")).read()
    if r.returncode != 0 or "Cost breakdown:" not in text:
        sys.exit(f"run.py: mpmFoam failed in {case}")
    block = text[text.index("Cost breakdown:"):].split("\n\n")[0]
    total = sum(float(x) for x in re.findall(r"\t([0-9.eE+-]+) s\t", block))
    return total/steps, text


def throughput(exe, cells, steps):
    """1-thread M point-steps/s of each shape function."""
    out = subprocess.run([exe, str(cells), str(steps)], capture_output=True, text=True).stdout
    rates = {}
    for line in out.splitlines():
        f = line.split()
        if len(f) >= 5 and f[1] == "1" and not line.startswith("#"):
            rates[f[0]] = float(f[4])
    return rates


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--steps", type=int, default=40, help="fluid steps per run")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--keep", action="store_true", help="keep the scratch folder")
    a = ap.parse_args()
    print(f"# effectsCost, {time.strftime('%Y-%m-%dT%H:%M:%S')}")
    print(f"# machine: {machine()}; load average at start {os.getloadavg()[0]:.2f}")
    tmp = tempfile.mkdtemp(prefix="effectsCost.")
    base, dt = prepare(tmp, a.steps)
    print(f"# scene: benchmarks/mppicComparison/mpmCase, {a.steps} fluid steps of {dt:g} s, "
          f"{a.rounds} rounds, OMP_NUM_THREADS=1", flush=True)

    names = [v[0] for v in VARIANTS]
    cases = {n: make_case(base, tmp, i, n) for i, n in enumerate(names)}
    cost = {n: [] for n in names}
    for r in range(a.rounds):
        for n in (names if r % 2 == 0 else reversed(names)):
            c, _ = run_case(cases[n], a.steps)
            cost[n].append(c)
        print(f"# round {r + 1} done, load {os.getloadavg()[0]:.2f}", flush=True)

    med = {n: statistics.median(cost[n]) for n in names}
    base_of = {v[0]: v[1] for v in VARIANTS}
    print(f"\n{'variant':26s} {'ms/fluid step':>14s} {'spread %':>9s} {'increment':>10s}")
    for n in names:
        ms = 1e3*med[n]
        spread = 100*(max(cost[n]) - min(cost[n]))/med[n]
        inc = "" if base_of[n] is None else f"{100*(med[n]/med[base_of[n]] - 1):+9.1f}%"
        print(f"{n:26s} {ms:14.2f} {spread:9.1f} {inc:>10s}")
    _, text = run_case(cases[names[5]], a.steps)
    print("\nEnd-of-run cost breakdown of '+ virtual mass' (one more run):")
    print(text[text.index("MPM summary"):].split("\n\n")[0])

    # The build switch: the core's step with and without the coupling hooks
    exes = [os.path.join(BUILD, "benchmarks", e) for e in ("particleThroughput", "particleThroughputNoCoupling")]
    if all(os.path.exists(e) for e in exes):
        rates = {e: [] for e in exes}
        for r in range(a.rounds):
            for e in (exes if r % 2 == 0 else reversed(exes)):
                rates[e].append(throughput(e, 20, 10))
        print("\nPure-MPM step with and without the fluid-coupling hooks "
              "(particleThroughput 20 10, 1 thread, median M point-steps/s):")
        print(f"{'shape':18s} {'with hooks':>11s} {'without':>9s} {'ratio':>7s}")
        for shape in rates[exes[0]][0]:
            w = statistics.median(x[shape] for x in rates[exes[0]])
            wo = statistics.median(x[shape] for x in rates[exes[1]])
            print(f"{shape:18s} {w:11.3f} {wo:9.3f} {w/wo:7.3f}")
    if a.keep:
        print(f"\n# cases kept in {tmp}")
    else:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    main()
