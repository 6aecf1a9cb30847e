#!/usr/bin/env python3
"""Cost per fluid step: mpmFoam (MPM grains + volume-averaged fluid) against
OpenFOAM's MPPIC solvers on the same scene, in one run.

Two scenes (--scene):
  bed  (default) the fluidised bed below, against MPPICFoam;
  vof  a block of the same grains released on the free surface of water in a
       tank open to the air (vof/mpmCase with fluidModel VOF, vof/mppicCase),
       against MPPICInterFoam: README.md, "The VOF scene".

Both cases (mpmCase/, mppicCase/) share the mesh (20 x 60 x 4 uniform 5 mm
hexes), the gas, the grains (0.5 mm glass, Gidaspow drag), the bed (0.1 m
deep, solid fraction 0.5), the inflow (0.6 m/s superficial), the fluid step
and the number of steps, the linear solvers and PIMPLE settings. There are as
many MPPICFoam parcels as MPM material points (8 per bed cell, 12800), at the
same positions (makePositions.py).

Variants, run in turn within each round (the order flips every round):
  mpm-stiff  druckerPrager E = 1e7 (tutorials/multiphase/fluidisedBed),
             subCycles auto: 21 MPM steps per fluid step
  mppic      MPPICFoam, column-tutorial sub-models
  mpm-E1e6   druckerPrager E = 1e6: still compresses under the bed's weight
             (~1.2 kPa at the plate) by < 0.1 %; sub-cycles ~ sqrt(E)
  mpm-soft   druckerPrager E = 2.5e4, subCycles auto: 1 MPM step per fluid
             step (the stable stand-in for "subCycles 1", see README)

Cost: from each log, over fluid steps warmup+1 .. N-1 (the start-up, the
injection and the last step are excluded): CPU ms/step from the solvers'
ExecutionTime (process CPU time) and wall ms/step from the time stamps at
which the "Time =" lines arrive. Every solver runs on one core
(OMP_NUM_THREADS=1; MPPICFoam is serial). The ratio mpm/mppic is formed
within each round and the median over the rounds is reported.

Usage (after `source etc/bashrc`):
    benchmarks/mppicComparison/run.sh [--scene bed|vof] [--steps 100]
        [--deltaT 5e-4] [--rounds 3] [--warmup 5] [--timeout 600] [--keep]
"""
import argparse
import filecmp
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.environ.get("MPMFOAM_DIR", os.path.abspath(os.path.join(HERE, "..", "..")))

# Each scene: its two case folders, the MPPIC solver, the box mpmSetParticles
# seeds (for makePositions.py), the files that must be identical in both
# cases, and whether alpha.water is set with setFields.
SCENES = {
    "bed": {"mpm": "mpmCase", "mppic": "mppicCase", "solver": "MPPICFoam",
            "box": ("0 0 0", "0.1 0.1 0.02"), "same": ["system/blockMeshDict"],
            "setFields": False},
    "vof": {"mpm": "vof/mpmCase", "mppic": "vof/mppicCase", "solver": "MPPICInterFoam",
            "box": ("0.02 0.15 0", "0.08 0.21 0.02"),
            "same": ["system/blockMeshDict", "system/fvSolution", "system/setFieldsDict",
                     "0/alpha.water.orig", "0/U", "0/p_rgh"],
            "setFields": True},
}

VARIANTS = {
    # name: (base case, {mpmProperties entry: value})
    "mpm-stiff": ("mpm", {}),
    "mppic": ("mppic", {}),
    "mpm-E1e6": ("mpm", {"materials/glass/E": "1e6"}),
    "mpm-soft": ("mpm", {"materials/glass/E": "2.5e4"}),
}


def sh(cmd, cwd, log):
    with open(os.path.join(cwd, log), "w") as f:
        r = subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT)
    if r.returncode != 0:
        sys.exit(f"run.py: {' '.join(cmd)} failed in {cwd} (see {log})")


def set_entry(case, dict_, entry, value):
    sh(["foamDictionary", "-entry", entry, "-set", str(value), dict_], case,
       "log.foamDictionary")


def machine():
    cpu = "?"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    try:
        commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                                capture_output=True, text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--", "src",
                                "applications"], capture_output=True, text=True).stdout
        commit += " (src/applications modified)" if dirty.strip() else ""
    except OSError:
        commit = "?"
    return cpu, os.cpu_count(), commit


def load():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def prepare(tmp, scene, steps, dt):
    """Builds the mpm and mppic base cases of a scene in tmp; returns their paths."""
    mpm = os.path.join(tmp, "mpm")
    mppic = os.path.join(tmp, "mppic")
    shutil.copytree(os.path.join(HERE, scene["mpm"]), mpm)
    shutil.copytree(os.path.join(HERE, scene["mppic"]), mppic)
    for f in scene["same"]:
        if not filecmp.cmp(os.path.join(mpm, f), os.path.join(mppic, f), shallow=False):
            sys.exit(f"run.py: the two cases have different {f}")
    for c in (mpm, mppic):
        set_entry(c, "system/controlDict", "deltaT", f"{dt:.10g}")
        set_entry(c, "system/controlDict", "endTime", f"{steps*dt:.10g}")
        sh(["blockMesh"], c, "log.blockMesh")
        if scene["setFields"]:
            shutil.copy(os.path.join(c, "0", "alpha.water.orig"), os.path.join(c, "0", "alpha.water"))
            sh(["setFields"], c, "log.setFields")
    sh(["mpmSetParticles"], mpm, "log.mpmSetParticles")
    lo, hi = scene["box"]
    sh([sys.executable, os.path.join(HERE, "makePositions.py"), ".",
        "--min", *lo.split(), "--max", *hi.split(), "--check",
        os.path.join(mpm, "0", "lagrangian", "materialPoints", "positions")],
       mppic, "log.makePositions")
    cells = [re.search(r"nCells:\s*(\d+)", open(os.path.join(c, "log.blockMesh")).read()).group(1)
             for c in (mpm, mppic)]
    return {"mpm": mpm, "mppic": mppic}, int(cells[0]), int(cells[1]), \
        open(os.path.join(mppic, "log.makePositions")).read().strip()


def run_case(base, workdir, name, edits, steps, warmup, mppic_solver, timeout):
    """Runs one solver on a fresh copy of base; returns the measurements. A
    run that takes longer than timeout seconds is stopped and counts as failed
    (an MPPIC parcel tracking that never ends has been seen: README.md)."""
    case = os.path.join(workdir, name)
    shutil.copytree(base, case)
    for entry, value in edits.items():
        set_entry(case, "constant/mpmProperties", entry, value)
    solver = mppic_solver if name.startswith("mppic") else "mpmFoam"
    env = dict(os.environ, OMP_NUM_THREADS="1")
    stamps, exec_t, subcycles, lines = [], [], [], []
    t0 = time.perf_counter()
    with open(os.path.join(case, "log." + solver), "w") as log:
        p = subprocess.Popen([solver], cwd=case, env=env, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True, bufsize=1)
        watchdog = threading.Timer(timeout, p.kill)
        watchdog.start()
        for line in p.stdout:
            now = time.perf_counter()
            log.write(line)
            lines.append(line)
            if line.startswith("Time = "):
                stamps.append(now)
            elif line.startswith("ExecutionTime = "):
                exec_t.append(float(line.split()[2]))
            elif line.startswith("MPM: ") and "sub-cycles" in line:
                subcycles.append(int(line.split()[1]))
        rc = p.wait()
        timed_out = not watchdog.is_alive()
        watchdog.cancel()
    wall_total = time.perf_counter() - t0
    text = "".join(lines)
    # mpmFoam's VOF line "alpha.water in [lo, hi]"; MPPICInterFoam's
    # "Max(alpha.water) = hi"
    bal = [abs(float(x)) for x in re.findall(r"balance \(V - V0 \+ out\)/V0 ([-0-9.eE+]+);", text)]
    amax = [float(x) for x in re.findall(r"alpha\.water in \[[^,]*, ([-0-9.eE+]+)\]", text)] \
        + [float(x) for x in re.findall(r"Max\(alpha\.water\) = ([-0-9.eE+]+)", text)]
    r = {"name": name, "rc": rc, "wallTotal": wall_total, "case": case}
    if rc != 0 or len(stamps) != steps or len(exec_t) != steps:
        r["ok"] = False
        m = re.search(r"(FOAM FATAL.*?\n.*?\n)", text, re.S)
        r["error"] = m.group(1).strip() if m else f"rc {rc}, {len(stamps)} of {steps} steps"
        if timed_out:
            r["error"] = f"stopped after {timeout} s in step {len(stamps)} of {steps}"
        return r
    n = steps - 1 - warmup     # steps warmup+1 .. steps-1
    r["ok"] = True
    r["alphaMax"] = max(amax) if amax else float("nan")
    r["waterBalance"] = max(bal) if bal else None
    r["cpu"] = 1e3*(exec_t[steps - 2] - exec_t[warmup - 1])/n
    r["wall"] = 1e3*(stamps[steps - 1] - stamps[warmup])/n
    if subcycles:
        win = subcycles[warmup:steps - 1]
        r["sub"] = (min(win), statistics.mean(win), max(win))
        m = re.search(r"Material points: (\d+)", text)
        r["particles"] = int(m.group(1)) if m else None
        cost = dict(re.findall(r"^\s+(P2G|nodal update|G2P|constitutive|I/O|fluid \(PIMPLE\))"
                               r"\s+([0-9.eE+-]+) s", text, re.M))
        if cost:
            fluid = float(cost.pop("fluid (PIMPLE)"))
            r["split"] = (1e3*fluid/steps, 1e3*sum(float(v) for v in cost.values())/steps)
    else:
        counts = [int(x) for x in re.findall(r"Current number of parcels\s+=\s+(\d+)", text)]
        r["particles"] = counts[0] if counts else None
        r["particlesEnd"] = counts[-1] if counts else None
        r["sub"] = None
    return r


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scene", choices=sorted(SCENES), default="bed",
                    help="bed: fluidised bed vs MPPICFoam; vof: grains into water vs MPPICInterFoam")
    ap.add_argument("--steps", type=int, default=100, help="fluid steps per run")
    ap.add_argument("--deltaT", type=float, default=5e-4, help="fluid step [s]")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--warmup", type=int, default=5, help="fluid steps left out at the start")
    ap.add_argument("--timeout", type=float, default=600, help="seconds per run at most")
    ap.add_argument("--keep", action="store_true", help="keep the scratch folder")
    a = ap.parse_args()
    if a.warmup < 1 or a.steps < a.warmup + 3:
        sys.exit("run.py: need --warmup >= 1 and --steps >= warmup + 3")

    scene = SCENES[a.scene]
    cpu, cores, commit = machine()
    print(f"date: {time.strftime('%Y-%m-%dT%H:%M:%S')}")
    print(f"cpu: {cpu}\ncores: {cores}\nsystem: {platform.system()} {platform.release()}")
    print(f"mpmFoam commit: {commit}")
    for exe in ("mpmFoam", scene["solver"]):
        path = shutil.which(exe) or "?"
        stamp = time.strftime("%Y-%m-%d %H:%M", time.localtime(os.path.getmtime(path))) \
            if path != "?" else "?"
        print(f"{exe}: {path} (built {stamp})")
    print(f"load average (1, 5, 15 min) at start: {load()}")
    print(f"scene {a.scene}: {a.steps} fluid steps of {a.deltaT:g} s, {a.rounds} rounds, "
          f"steps {a.warmup + 1}..{a.steps - 1} timed, OMP_NUM_THREADS=1", flush=True)

    tmp = tempfile.mkdtemp(prefix="mppicComparison.")
    t_start = time.perf_counter()
    bases, cells_mpm, cells_mppic, pos_log = prepare(tmp, scene, a.steps, a.deltaT)
    print(f"mesh: {cells_mpm} cells (mpmCase), {cells_mppic} cells (mppicCase)")
    print(pos_log.replace("\n", "\n"), flush=True)

    order = list(VARIANTS)
    results = {k: [] for k in order}
    for rnd in range(a.rounds):
        seq = order if rnd % 2 == 0 else order[::-1]
        for name in seq:
            base, edits = VARIANTS[name]
            r = run_case(bases[base], os.path.join(tmp, f"round{rnd}"), name, edits,
                         a.steps, a.warmup, scene["solver"], a.timeout)
            results[name].append(r)
            if r["ok"]:
                sub = f", {r['sub'][1]:.3g} MPM steps/fluid step" if r["sub"] else ""
                print(f"round {rnd} {name:10s}: {r['cpu']:8.2f} ms CPU, {r['wall']:8.2f} ms "
                      f"wall per fluid step{sub} (load {load()})", flush=True)
            else:
                print(f"round {rnd} {name:10s}: FAILED: {r['error']}", flush=True)

    # Ratios within each round
    print(f"\nload average (1, 5, 15 min) at end: {load()}")
    print(f"benchmark wall time: {time.perf_counter() - t_start:.0f} s\n")
    ref = results["mppic"]
    hdr = ("| solver | MPM steps per fluid step | particles | CPU ms/fluid step "
           f"| wall ms/fluid step | ratio to {scene['solver']} (CPU) | ratio (wall) |")
    print(hdr)
    print("|" + "---|"*7)
    for name in order:
        rs = [r for r in results[name] if r["ok"]]
        if not rs:
            print(f"| {name} | failed | | | | | |")
            continue
        cpu_ = statistics.median(r["cpu"] for r in rs)
        wall = statistics.median(r["wall"] for r in rs)
        if name == "mppic":
            sub, ratio_c, ratio_w = "- (no sub-cycling)", "1", "1"
            parts = f"{rs[0]['particles']} parcels"
        else:
            lo = min(r["sub"][0] for r in rs)
            hi = max(r["sub"][2] for r in rs)
            sub = f"{lo}" if lo == hi else f"{lo}-{hi}"
            parts = f"{rs[0]['particles']} points"
            rc = [r["cpu"]/m["cpu"] for r, m in zip(results[name], ref) if r["ok"] and m["ok"]]
            rw = [r["wall"]/m["wall"] for r, m in zip(results[name], ref) if r["ok"] and m["ok"]]
            ratio_c = f"{statistics.median(rc):.2f} ({min(rc):.2f}-{max(rc):.2f})" if rc else "-"
            ratio_w = f"{statistics.median(rw):.2f} ({min(rw):.2f}-{max(rw):.2f})" if rw else "-"
        print(f"| {name} | {sub} | {parts} | {cpu_:.1f} | {wall:.1f} | {ratio_c} | {ratio_w} |")
    print("\n(median over the rounds; ratios: median (min-max) of the per-round ratios)")

    print("\nmpmFoam split per fluid step (the solver's own wall-clock timers, all steps, "
          "median):")
    for name in order:
        rs = [r for r in results[name] if r["ok"] and r.get("split")]
        if rs:
            f = statistics.median(r["split"][0] for r in rs)
            m = statistics.median(r["split"][1] for r in rs)
            print(f"  {name}: fluid (PIMPLE) {f:.1f} ms, MPM (P2G+nodal+G2P+constitutive+I/O) "
                  f"{m:.1f} ms")
    ends = [r.get("particlesEnd") for r in results["mppic"] if r["ok"]]
    if ends:
        print(f"{scene['solver']} parcels at the end: {ends}")
    if a.scene == "vof":
        print("largest alpha.water over each run (1 where the water is bounded): "
              + ", ".join(f"{name} {max(r['alphaMax'] for r in results[name] if r['ok']):.4g}"
                          for name in order if any(r["ok"] for r in results[name])))
        wb = [(name, max(r["waterBalance"] for r in results[name] if r["ok"]))
              for name in order if any(r["ok"] and r.get("waterBalance") is not None for r in results[name])]
        if wb:
            print("mpmFoam's water balance |(V - V0 + out)/V0|, largest over each run: "
                  + ", ".join(f"{n} {b:.2g}" for n, b in wb))

    if a.keep:
        print(f"\ncases kept in {tmp}")
    else:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
