#!/usr/bin/env python3
"""Parameter studies of the coupled spectral analysis (docs/stabilityAnalysis.md
section 7b), starting from a case's dictionaries. Not the case advisor: a
case's time-step advice is the solver's, `mpmAdviseTimeStep <case>` (mpmFoam
-adviseTimeStep: the case set up as a run sets it up, h from the lattice,
the solid fraction from the seeded points). Without an override this script
runs exactly that, so a case has one answer from one code path.

With an override (--h, --aS, --stress-free) it studies the case's
parameters with one of them changed, e.g. a lifted bed (--stress-free --aS
0.55) or another cell size. It reads the dictionaries (controlDict deltaT,
blockMeshDict h unless --h, transportProperties, mpmProperties: shape,
transfer and flipRatio (APIC as PIC, as the solver maps it), stressUpdate,
timeStep courant, coupling mode and forces, the first material with a drag;
mpmSetParticlesDict: the largest solidFraction capped at alphaMax, unless
--aS; fvSolution: PIMPLE nCorrectors) and runs
`mpmStabilityAnalysis --model coupled --advise` with them: the same lines
as the solver's advice, for the changed parameters.

Usage: adviseCoupledCase.py <case>                    (= mpmAdviseTimeStep <case>)
       adviseCoupledCase.py <case> [--tool path] [--aS a] [--h h] [--stress-free]
"""
import os
import re
import shutil
import subprocess
import sys


def tokens(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    return re.findall(r'"[^"]*"|[{}();]|[^\s{}();]+', text)


def parse(toks, i=0):
    """OpenFOAM dictionary -> nested dict; values are token lists."""
    d = {}
    while i < len(toks) and toks[i] != "}":
        key = toks[i]
        i += 1
        if i < len(toks) and toks[i] == "{":
            d[key], i = parse(toks, i + 1)
            i += 1
            continue
        val, depth = [], 0
        while i < len(toks) and not (toks[i] == ";" and depth == 0):
            depth += toks[i] == "("
            depth -= toks[i] == ")"
            val.append(toks[i])
            i += 1
        d[key] = val
        i += 1
    return d, i


def read(case, *path):
    with open(os.path.join(case, *path)) as f:
        return parse(tokens(f.read()))[0]


def scalar(d, key, default=None):
    if key not in d:
        if default is None:
            raise KeyError(key)
        return default
    return float(d[key][0])


def option(name, default=None):
    return sys.argv[sys.argv.index(name) + 1] if name in sys.argv else default


def main():
    if len(sys.argv) < 2 or sys.argv[1].startswith("-"):
        print(__doc__)
        sys.exit(1)
    case = sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    if not any(o in sys.argv for o in ("--h", "--aS", "--stress-free")):
        # No override: the case's advice, which is the solver's
        advisor = shutil.which("mpmAdviseTimeStep") or os.path.join(here, "..", "..", "..", "bin", "mpmAdviseTimeStep")
        print(f"adviseCoupledCase.py: no override (--h, --aS, --stress-free): the case's advice "
              f"is the solver's: mpmAdviseTimeStep {case}")
        sys.stdout.flush()
        sys.exit(subprocess.run([advisor, case]).returncode)
    tool = option("--tool", os.path.join(os.environ.get("MPMFOAM_BUILD", ""),
                                         "applications/tools/mpmStabilityAnalysis/mpmStabilityAnalysis"))
    control = read(case, "system", "controlDict")
    mesh = read(case, "system", "blockMeshDict")
    transport = read(case, "constant", "transportProperties")
    mpm = read(case, "constant", "mpmProperties")
    seeding = read(case, "system", "mpmSetParticlesDict")
    # PIMPLE nCorrectors (OpenFOAM's default 1), as the solver's advice takes it
    correctors = read(case, "system", "fvSolution").get("PIMPLE", {}).get("nCorrectors", ["1"])[0]
    h = option("--h") or (mesh["h"][0] if "h" in mesh else None)
    if h is None:
        sys.exit("adviseCoupledCase: blockMeshDict has no 'h': give the cell size with --h "
                 "(mpmAdviseTimeStep <case> reads it from the mesh)")
    coupling = mpm["coupling"]
    forces = [t for t in coupling["forces"] if t not in "()"]
    materials = mpm["materials"]
    name, mat = next(((n, m) for n, m in materials.items() if isinstance(m, dict) and "drag" in m), (None, None))
    if mat is None:
        sys.exit("adviseCoupledCase: no material with a drag sub-dictionary")
    drag = mat["drag"]
    law_coeffs = ",".join(f"{k}={v[0]}" for k, v in mat.items() if k not in ("model", "drag") and not isinstance(v, dict))
    drag_coeffs = ",".join(f"{k}={v[0]}" for k, v in drag.items() if k != "model")
    fractions = [scalar(r, "solidFraction", 1.0) for r in seeding.get("regions", {}).values() if isinstance(r, dict)]
    a_s = option("--aS", repr(min(max(fractions), scalar(coupling, "alphaMax", 0.63))))
    shape = {"linearHat": "LH", "quadraticBSpline": "QBS", "cubicBSpline": "CBS"}[mpm["shapeFunction"][0]]
    courant = mpm.get("timeStep", {}).get("courant", ["0.5"])[0]
    # The solver's mapping (analysedStep, stableCourant.C): APIC, which
    # ignores flipRatio, as PIC; otherwise flipRatio, 0.99 when absent
    apic = mpm.get("transfer", ["PICFLIP"])[0] in ("APIC", "apic")
    alpha = "0" if apic else mpm.get("flipRatio", ["0.99"])[0]
    law = "dilute" if "--stress-free" in sys.argv else mat["model"][0]
    args = [tool, "--model", "coupled", "--advise",
            "--law", law, "--law-coeffs", law_coeffs if law != "dilute" else f"rho={mat['rho'][0]}",
            "--drag", drag["model"][0], "--drag-coeffs", drag_coeffs,
            "--rho-f", transport["rho"][0], "--nu-f", transport["nu"][0],
            "--h", h, "--fluid-dt", control["deltaT"][0], "--aS", a_s, "--courant", courant,
            "--shape", shape, "--alpha", alpha,
            "--scheme", mpm.get("stressUpdate", ["USL"])[0],
            "--mode", coupling.get("mode", ["twoWay"])[0], "--forces", ",".join(forces),
            "--correctors", correctors]
    print(f"adviseCoupledCase.py: a parameter study, not the case's advice (that is mpmAdviseTimeStep {case})")
    print(f"case {case}: material {name} ({law}), " + " ".join(args[3:]))
    sys.stdout.flush()
    sys.exit(subprocess.run(args).returncode)


if __name__ == "__main__":
    main()
