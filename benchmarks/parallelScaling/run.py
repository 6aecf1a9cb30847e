#!/usr/bin/env python3
"""Strong scaling of decomposed mpmFoam runs on this machine.

Two scenes, each run on 1 rank, 2 ranks (pure MPI), 1 rank x 2 OpenMP
threads, 2 ranks x 2 threads, and 3 and 4 ranks (oversubscribed on a
2-core machine: reported as what they are):
  block3D  a 3D elastic slab thrown across a 32^3 box (about 190 000
           points, cubic B-splines, 60 fixed steps, no writes), decomposed
           in slices along x (simple, N 1 1), so the points are balanced;
  block3DOwn  block3D on a lattice of its own (the same cells), balanced
           by points (latticeBalance), on 1 and 2 ranks;
  slide    a block sliding from one end of the box to the other, on 2
           ranks split across x, with and without the balance by points:
           max/mean points per rank over time;
  collapse3D  the 3D granular collapse tutorial (200 960 points), its first
           0.03 s, balanced by points, on 1 and 2 ranks and 1 rank x 2
           threads;
  coupled  the underwater granular column collapse tutorial at half its
           cell size (12 800 points in water, 200 x 100 cells), 40 fluid
           steps with their MPM sub-cycles, decomposed in slices along y.
Times are the step loop's own (the cost summary each run prints: every
phase's maximum over ranks; start-up and writing excluded), so ratios are
taken within one run of this script on one machine. Prints a table and
the share of each step spent in halo exchange and in migration. Each scene
also runs two serial copies at once ("2x1"): two workers that never
communicate, whose 2 t1/t is the most any 2-worker run can reach here.

    benchmarks/parallelScaling/run.sh [--scenes block3D coupled] [--keep]
"""
import argparse
import os
import platform
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

CONFIGS = [  # (ranks, threads)
    (1, 1), (2, 1), (1, 2), (2, 2), (3, 1), (4, 1)]


def sh(cmd, cwd, env=None):
    r = subprocess.run(cmd, cwd=cwd, shell=True, env=env, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        sys.stderr.write(r.stdout[-3000:])
        raise SystemExit("failed: %s (in %s)" % (cmd, cwd))
    return r.stdout


def make_block3D(d):
    shutil.copytree(os.path.join(ROOT, "tests/cases/parallelCases/block3D"), d)
    sub = [("system/blockMeshDict", r"\(14 14 14\)", "(32 32 32)"),
           ("system/mpmSetParticlesDict", r"min \([^)]*\); max \([^)]*\);",
            "min (0.0 0.0 0.1); max (1.0 1.0 0.45);"),
           ("system/controlDict", r"endTime 0.8;", "endTime 0.09;"),
           ("system/controlDict", r"deltaT 1e-3;", "deltaT 1.5e-3;"),
           ("system/controlDict", r"writeControl adjustableRunTime; writeInterval 0.4;",
            "writeControl timeStep; writeInterval 100000;"),
           ("constant/mpmProperties", r"timeStep \{[^}]*\}", "timeStep { type fixed; }"),
           ("constant/mpmProperties", r"logInterval +1;", "logInterval 10;")]
    for f, a, b in sub:
        p = os.path.join(d, f)
        s = open(p).read()
        s2 = re.sub(a, b, s)
        assert s2 != s, (f, a)
        open(p, "w").write(s2)
    sh("blockMesh && mpmSetParticles", d)


def make_block3DOwn(d):
    """block3D on a lattice of its own (an extent around the whole box: the
    same cells), so that the lattice's owners follow the points: balanced
    at the start and again whenever max/mean exceeds 1.1 (latticeBalance)."""
    make_block3D(d)
    with open(os.path.join(d, "constant/mpmProperties"), "a") as f:
        f.write("\nlattice { extent ((-1 -1 -1) (2 2 2)); }\n")


def make_slide(d):
    """A block that slides from one end of the box to the other: 0.2 m of
    the 1 m box's x at 2.5 m/s, 0.32 s (the far side by the end), no
    gravity, on slip sides (the scene that defeats a static split)."""
    make_block3D(d)
    sub = [("system/mpmSetParticlesDict", r"min \([^)]*\); max \([^)]*\);",
            "min (0.0 0.2 0.2); max (0.2 0.8 0.8);"),
           ("system/mpmSetParticlesDict", r"value \([^)]*\);", "value (2.5 0 0);"),
           ("system/controlDict", r"endTime 0.09;", "endTime 0.32;"),
           ("constant/mpmProperties", r"floor \{[^}]*\}", "floor { type slip; }"),
           ("constant/g", r"\([^)]*\)", "(0 0 0)")]
    for f, a, b in sub:
        p = os.path.join(d, f)
        s = open(p).read()
        s2 = re.sub(a, b, s, count=1)
        assert s2 != s, (f, a)
        open(p, "w").write(s2)
    sh("rm -rf 0/lagrangian && mpmSetParticles", d)


def run_slide(base):
    """The slide on 2 ranks split across x (simple), the lattice's owners
    following the mesh (balance none) and balanced by points: max/mean
    points per rank over time, and the step loop's time."""
    rows = {}
    for balance in ("none", "scotch"):
        d = base + "." + balance
        shutil.copytree(base, d)
        with open(os.path.join(d, "constant/mpmProperties"), "a") as f:
            f.write("\nlattice { balance %s; }\n" % balance)
        decompose(d, 2, 0)
        log = sh("mpirun -np 2 mpmFoam -parallel", d, dict(os.environ, OMP_NUM_THREADS="1"))
        imb = [float(b)/float(a) for a, b in
               re.findall(r"points per processor min \d+, mean ([0-9.e+]+), max (\d+)", log)]
        rows[balance] = (summary(log), imb)
    print("\nslide: %d points, %d MPM steps, 2 ranks split across x" % (
        rows["none"][0]["points"], rows["none"][0]["steps"]))
    print("max/mean points per rank every logInterval (10 steps):")
    for balance, (t, imb) in rows.items():
        print("  balance %-6s %s" % (balance, " ".join("%.2f" % x for x in imb)))
    for balance, (t, imb) in rows.items():
        print("  balance %-6s loop %.3f s, mean max/mean %.3f, %d partitions (%.1f %% of the loop)" % (
            balance, t["loop"], sum(imb)/len(imb), t["rebalances"],
            100*t["balance"]/t["loop"] if t["loop"] else 0))


def make_collapse3D(d):
    """The 3D granular collapse tutorial (200 960 points, quadratic B-splines,
    Drucker-Prager), its first 0.03 s (about 110 steps), no writes: balanced
    by points (latticeBalance) on 2 ranks."""
    shutil.copytree(os.path.join(ROOT, "tutorials/mpm/granularCollapse3D"), d,
                    ignore=shutil.ignore_patterns("[1-9]*", "0.*", "processor*", "log.*", "*.png",
                                                  "sweep", "HDF5", "*.csv"))
    p = os.path.join(d, "system/controlDict")
    s = open(p).read()
    for a, b in [(r"\nendTime .*", "\nendTime 0.03;"), (r"\nwriteInterval .*", "\nwriteInterval 100;")]:
        s2 = re.sub(a, b, s)
        assert s2 != s, a
        s = s2
    open(p, "w").write(s)
    sh("blockMesh && mpmSetParticles", d)


def make_coupled(d):
    shutil.copytree(os.path.join(ROOT, "tutorials/multiphase/underwaterGranularCollapse"), d,
                    ignore=shutil.ignore_patterns("[1-9]*", "0.*", "processor*", "log.*", "*.png"))
    p = os.path.join(d, "system/blockMeshDict")
    s = open(p).read()
    for a, b in [("dz  0.01;", "dz  0.005;"), ("nx  100;", "nx  200;"), ("ny  50;", "ny  100;")]:
        assert a in s, a
        s = s.replace(a, b)
    open(p, "w").write(s)
    p = os.path.join(d, "system/mpmSetParticlesDict")
    s = open(p).read()
    s = re.sub(r"max +\(0.2 0.4 0.01\);", "max (0.2 0.4 0.005);", s)
    open(p, "w").write(s)
    p = os.path.join(d, "system/controlDict")
    s = open(p).read()
    s = re.sub(r"\nendTime .*", "\nendTime 0.04;", s)
    s = re.sub(r"\nwriteControl .*", "\nwriteControl timeStep;", s)
    s = re.sub(r"\nwriteInterval .*", "\nwriteInterval 100000;", s)
    open(p, "w").write(s)
    sh("blockMesh && mpmSetParticles", d)


def decompose(d, n, axis):
    split = ["1", "1", "1"]
    split[axis] = str(n)
    with open(os.path.join(d, "system/decomposeParDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
                "numberOfSubdomains %d;\nmethod simple;\ncoeffs { n (%s); }\n" % (n, " ".join(split)))
    sh("rm -rf processor* && decomposePar -force", d)


def summary(log):
    """Phase times (s) of the cost summary, and the point-steps."""
    t = {}
    for name, key in [("P2G", "p2g"), ("nodal update", "nodal"), ("G2P", "g2p"),
                      ("constitutive", "constitutive"),
                      ("migration", "migration"), ("load balance", "balance"),
                      ("fluid \\(PIMPLE\\)", "fluid")]:
        m = re.search(r"^\s+" + name + r"\s+([0-9.eE+-]+) s", log, re.M)
        t[key] = float(m.group(1)) if m else 0.0
    # The halo's share, printed under each phase it is part of
    t["halo"] = sum(float(x) for x in re.findall(r"^\s+of which halo\s+([0-9.eE+-]+) s", log, re.M))
    m = re.search(r"MPM summary: (\d+) material points, (\d+) steps", log)
    t["points"], t["steps"] = int(m.group(1)), int(m.group(2))
    t["loop"] = sum(t[k] for k in ("p2g", "nodal", "g2p", "constitutive", "migration", "balance", "fluid"))
    t["rebalances"] = len(re.findall(r"^MPM load balance at time", log, re.M))
    m = re.findall(r"points per processor min \d+, mean ([0-9.e+]+), max (\d+)", log)
    t["imbalance"] = float(m[-1][1])/float(m[-1][0]) if m else 1.0
    return t


def run_scene(name, base, cores, axis, configs=CONFIGS):
    rows = []
    for ranks, threads in configs:
        d = base + ".%dx%d" % (ranks, threads)
        shutil.copytree(base, d)
        env = dict(os.environ, OMP_NUM_THREADS=str(threads))
        if ranks == 0:
            # two independent serial runs at once (no communication at all):
            # what this machine gives two workers; the loop is the slower one's
            shutil.copytree(base, d + "b")
            procs = [subprocess.Popen("mpmFoam", cwd=c, shell=True, env=env, stdout=subprocess.PIPE,
                                      stderr=subprocess.STDOUT, text=True) for c in (d, d + "b")]
            logs = [p.communicate()[0] for p in procs]
            t = [summary(l) for l in logs]
            rows.append((ranks, threads, max(t, key=lambda x: x["loop"])))
            continue
        if ranks == 1:
            log = sh("mpmFoam", d, env)
        else:
            decompose(d, ranks, axis)
            log = sh("mpirun -np %d mpmFoam -parallel" % ranks, d, env)
        rows.append((ranks, threads, summary(log)))
    t1 = rows[0][2]["loop"]
    print("\n%s: %d points, %d MPM steps" % (name, rows[0][2]["points"], rows[0][2]["steps"]))
    print("%-6s %-7s %-10s %-8s %-10s %-8s %-9s %-9s %s" % (
        "ranks", "threads", "loop [s]", "speedup", "efficiency", "halo %", "migr. %", "max/mean", "note"))
    for ranks, threads, t in rows:
        if ranks == 0:
            # 2 serial runs at once, each the whole work: the speed-up two
            # workers could reach here is 2 t1/t
            print("%-6s %-7d %-10.3f %-8.2f %-10.2f %-8s %-9s %-9s %s" % (
                "2x1", threads, t["loop"], 2*t1/t["loop"], t1/t["loop"], "-", "-", "-",
                "two serial runs at once: this machine's ceiling for 2 workers (2 t1/t)"))
            continue
        used = ranks*threads
        note = "oversubscribed (%d processes on %d cores)" % (used, cores) if used > cores else ""
        print("%-6d %-7d %-10.3f %-8.2f %-10.2f %-8.1f %-9.1f %-9.2f %s" % (
            ranks, threads, t["loop"], t1/t["loop"], t1/t["loop"]/min(used, cores),
            100*t["halo"]/t["loop"], 100*t["migration"]/t["loop"], t["imbalance"],
            note + ("%d partitions by points, %.1f %% of the loop" % (t["rebalances"], 100*t["balance"]/t["loop"])
                    if t["rebalances"] else "")))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scenes", nargs="*", default=["block3D", "block3DOwn", "collapse3D", "coupled", "slide"])
    ap.add_argument("--keep", action="store_true")
    args = ap.parse_args()
    cores = os.cpu_count()
    cpu = ""
    try:
        cpu = [l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")][0]
    except Exception:
        pass
    print("machine: %s, %d cores, %s" % (cpu, cores, platform.platform()))
    work = tempfile.mkdtemp(prefix="parallelScaling.")
    try:
        for scene in args.scenes:
            base = os.path.join(work, scene)
            {"block3D": make_block3D, "block3DOwn": make_block3DOwn, "coupled": make_coupled,
             "slide": make_slide, "collapse3D": make_collapse3D}[scene](base)
            if scene == "slide":
                run_slide(base)
                continue
            configs = {"block3DOwn": CONFIGS[:2] + [(0, 1)],
                       "collapse3D": CONFIGS[:3] + [(0, 1)]}.get(scene, CONFIGS + [(0, 1)])
            run_scene(scene, base, cores, {"block3D": 0, "block3DOwn": 0, "coupled": 1, "collapse3D": 0}[scene],
                      configs)
    finally:
        if args.keep:
            print("\ncases kept in", work)
        else:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
