"""The solver's own one-thread rate on a pure-MPM 3D block.

The block of benchmarks/parallelScaling (a 3D elastic slab thrown across a
32^3 box, USL, FLIP 0.99, lumped mass, 60 fixed steps, no writes), deeper
(z 0.1 to 0.52: about 110 000 points), with the shape function asked for
(quadratic B-splines by default), run by mpmFoam on one OpenMP thread. The
figure is the solver's own "M point-steps/s" (its MPM summary: points times
steps over the MPM phases' time), with the phases' shares.

With --base DIR (another checkout, built, with its own etc/bashrc) both
builds run the same case in turn, A B A B, and each pair gives a ratio
(this checkout over the base); medians are printed. Ratios within one run,
on an idle machine: other processes on the cores move both figures.

    benchmarks/solverRate/run.sh [--shape quadraticBSpline] [--rounds 3] [--base DIR]
"""
import argparse
import importlib.util
import os
import platform
import re
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
# benchmarks/parallelScaling/run.py: its block (make_block3D) and sh
_spec = importlib.util.spec_from_file_location("parallelScaling", os.path.join(ROOT, "benchmarks", "parallelScaling", "run.py"))
scaling = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scaling)


def make_case(d, shape):
    scaling.make_block3D(d)
    for f, a, b in [("system/mpmSetParticlesDict", r"max \(1\.0 1\.0 0\.45\);", "max (1.0 1.0 0.52);"),
                    ("constant/mpmProperties", r"shapeFunction +cubicBSpline;", "shapeFunction %s;" % shape)]:
        p = os.path.join(d, f)
        s = open(p).read()
        s2 = re.sub(a, b, s)
        assert s2 != s, (f, a)
        open(p, "w").write(s2)
    scaling.sh("rm -rf 0/lagrangian && mpmSetParticles", d)


def run_once(case, build):
    """mpmFoam of `build` (a checkout) on one thread: the summary's rate and shares."""
    env = dict(os.environ, OMP_NUM_THREADS="1")
    log = scaling.sh("bash -c '. %s/etc/bashrc >/dev/null && mpmFoam'" % build, case, env)
    m = re.search(r"MPM summary: (\d+) material points, (\d+) steps, ([0-9.eE+-]+) M point-steps/s", log)
    if not m:
        raise SystemExit("no MPM summary in the log of %s" % build)
    shares = {k: float(v) for k, v in re.findall(r"^\s+(P2G|nodal update|G2P|constitutive)\s+\S+ s\s+([0-9.eE+-]+) %", log, re.M)}
    return int(m.group(1)), int(m.group(2)), float(m.group(3)), shares


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--shape", default="quadraticBSpline", choices=["linearHat", "quadraticBSpline", "cubicBSpline"])
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--base", help="another built checkout to compare with, in turn")
    args = ap.parse_args()
    cpu = [l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")][0]
    print("# solverRate: %s, %d cores, %s, load average %.2f" % (cpu, os.cpu_count(), platform.platform(), os.getloadavg()[0]))
    builds = [("this", ROOT)] + ([("base", os.path.abspath(args.base))] if args.base else [])
    rates = {name: [] for name, _ in builds}
    with tempfile.TemporaryDirectory(prefix="solverRate.") as tmp:
        case = os.path.join(tmp, "block")
        make_case(case, args.shape)
        print("%-6s %-5s %8s %6s %12s %6s %6s %6s %6s" % ("round", "build", "points", "steps", "Mpt-steps/s", "P2G%", "nodal%", "G2P%", "stress%"))
        for r in range(args.rounds):
            order = builds if r % 2 == 0 else builds[::-1]
            for name, path in order:
                n, steps, rate, sh = run_once(case, path)
                rates[name].append(rate)
                print("%-6d %-5s %8d %6d %12.3f %6.1f %6.1f %6.1f %6.1f" % (
                    r + 1, name, n, steps, rate, sh.get("P2G", 0), sh.get("nodal update", 0), sh.get("G2P", 0),
                    sh.get("constitutive", 0)), flush=True)
    print("\n%s, one thread: median %.3f M point-steps/s (%s)" % (
        args.shape, statistics.median(rates["this"]), ", ".join("%.3f" % x for x in rates["this"])))
    if args.base:
        ratios = [a/b for a, b in zip(rates["this"], rates["base"])]
        print("base (%s): median %.3f M point-steps/s; this/base per round %s, median %.3f" % (
            args.base, statistics.median(rates["base"]), ", ".join("%.3f" % x for x in ratios), statistics.median(ratios)))


if __name__ == "__main__":
    main()
