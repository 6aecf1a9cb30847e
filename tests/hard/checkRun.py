#!/usr/bin/env python3
"""The stress suite's shared checks on one finished (or stopped) run.

    checkRun.py CASE [--log log.mpmFoam] [--energy-growth G] [--energy-source S]
                [--energy-window P]
                [--alpha-max A] [--expect-stop REGEX] [--removed N]

Asserts, printing PASS/FAIL with the measured figure:
  - outcome: the log ends with "End" and has no FOAM FATAL ERROR, or, with
    --expect-stop, it stops with a FOAM FATAL ERROR whose text matches REGEX
    (a message that says what to change);
  - no NaN or inf in any written file of any time (fields, cloud) nor in the
    solver's log before a stop;
  - points and mass: every written cloud holds the points mpmSetParticles
    logged ("Writing N material points (total mass M)") minus --removed, each
    id once, each with its seeded mass (relative 1e-14), the total to 1e-12;
    with open boundaries, their ledger (postProcessing/openBoundaries/*/
    massBalance.dat) at each write time: initial + injected - removed =
    present, and the cloud holds that many points and that mass;
  - energy (postProcessing/mpmSummary, kinetic + elastic + potential, every
    logged step): max_t (E(t) - E(0)) <= G * E_avail + S, with E_avail =
    KE(0) + SE(0) + PE(0) - min_t PE(t) (all the energy that can become
    motion) and S an absolute allowance for a stated source (a driving fluid);
  - with --energy-window P: the mean energy over the last P (a period) is
    <= that over the first P (no upward trend);
  - with --alpha-max: the solid fraction the fluid sees, 1 - alpha.fluid, is
    <= alphaMax in every written field (and the raw lattice alpha.solid's max
    is reported).
The case must be written in ASCII (writeFormat ascii).
Last line: "figures: name=value ..." for the report.
"""
import argparse
import glob
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "etc", "python"))
import mpmPost  # noqa: E402

NONFINITE = re.compile(rb"(?<![\w.>-])[-+]?(nan|inf)(?![\w])", re.IGNORECASE)

failures = 0
figures = {}


def check(what, ok, detail):
    global failures
    print(("PASS: " if ok else "FAIL: ") + what + "  [" + detail + "]")
    if not ok:
        failures += 1


def timeDirs(case):
    out = []
    for d in os.listdir(case):
        try:
            out.append((float(d), d))
        except ValueError:
            pass
    return [d for _, d in sorted(out)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case")
    ap.add_argument("--log", default="log.mpmFoam")
    ap.add_argument("--energy-growth", type=float, default=None)
    ap.add_argument("--energy-source", type=float, default=0.0)
    ap.add_argument("--energy-window", type=float, default=None)
    ap.add_argument("--alpha-max", type=float, default=None)
    ap.add_argument("--expect-stop", default=None)
    ap.add_argument("--removed", type=int, default=0)
    a = ap.parse_args()
    c = a.case

    # ---- outcome -----------------------------------------------------------
    log = open(os.path.join(c, a.log), "rb").read()
    fatal = log.find(b"FOAM FATAL")
    ended = re.search(rb"^End\s*$", log, re.M) is not None
    if a.expect_stop:
        text = log[fatal:].decode(errors="replace") if fatal >= 0 else ""
        m = re.search(a.expect_stop, text, re.S)
        check("the run stops with a message saying what to change",
              fatal >= 0 and m is not None,
              "/" + a.expect_stop + "/: " + (re.sub(r"\s+", " ", m.group(0))[:160] if m else "no match"))
    else:
        check("the run completes (End, no FOAM FATAL)", ended and fatal < 0,
              "End %s, fatal %s" % (ended, fatal >= 0))
    steps = re.findall(rb"^MPM: step (\d+)", log, re.M)
    figures["steps"] = int(steps[-1]) if steps else 0

    # ---- NaN / inf -----------------------------------------------------------
    before = log if fatal < 0 else log[:fatal]
    bad = NONFINITE.search(before)
    check("no NaN/inf in the solver log" + (" before the stop" if fatal >= 0 else ""),
          bad is None, "first: " + (before[max(0, bad.start() - 60):bad.end()].decode(errors="replace").replace("\n", " | ") if bad else "none"))
    nFiles, badFiles = 0, []
    for t in timeDirs(c):
        for f in glob.glob(os.path.join(c, t, "**", "*"), recursive=True):
            if os.path.isfile(f):
                nFiles += 1
                if NONFINITE.search(open(f, "rb").read()):
                    badFiles.append(os.path.relpath(f, c))
    check("no NaN/inf in any written file", not badFiles,
          "%d files; bad: %s" % (nFiles, " ".join(badFiles[:3]) or "none"))

    # ---- points and mass -----------------------------------------------------
    m = re.findall(r"^Writing (\d+) material points \(total mass ([^)]*)\)",
                   open(os.path.join(c, "log.mpmSetParticles")).read(), re.M)
    nSeed, mSeed = int(m[-1][0]), float(m[-1][1])
    ts = mpmPost.times(c)
    # Open boundaries (inlets, outlets): the solver's exact ledger,
    # postProcessing/openBoundaries/<t0>/massBalance.dat, gives what entered
    # and left by each write time
    ledger = {}
    for f in sorted(glob.glob(os.path.join(c, "postProcessing", "openBoundaries", "*", "massBalance.dat"))):
        for row in np.loadtxt(f, comments="#", ndmin=2):
            ledger[round(row[0], 9)] = row
    removedTotal = a.removed

    def cloud(t):
        ids = mpmPost.read_cloud_field(c, t, "pointId").astype(np.int64).reshape(-1)
        mass = mpmPost.read_cloud_field(c, t, "mass").reshape(-1)
        o = np.argsort(ids)
        return ids[o], mass[o]
    ids0, m0 = cloud(ts[0])
    seeded = dict(zip(ids0.tolist(), m0.tolist()))
    worstCount, worstMass, worstPoint, dupes, ledgerRows = 0, 0.0, 0.0, 0, 0
    for t in ts:
        ids, mass = cloud(t)
        expected, expectedMass = nSeed - (a.removed if t != ts[0] else 0), mSeed
        row = ledger.get(round(float(t), 9))
        if row is not None:
            # initial + injected - removed = present, exactly, and the cloud
            # on disk is what the ledger says is present
            ledgerRows += 1
            expected = int(row[1] + row[3] - row[5])
            expectedMass = row[2] + row[4] - row[6]
            removedTotal = int(row[5])
            worstCount = max(worstCount, abs(int(row[7]) - expected))
        worstCount = max(worstCount, abs(len(ids) - expected))
        dupes += len(ids) - len(np.unique(ids))
        known = np.array([i in seeded for i in ids.tolist()])
        if known.any():
            ref = np.array([seeded[i] for i in ids[known].tolist()])
            worstPoint = max(worstPoint, np.abs(mass[known] - ref).max()/m0.max())
        if a.removed == 0 or row is not None:
            worstMass = max(worstMass, abs(mass.sum()/expectedMass - 1))
    figures.update(points=nSeed, times=len(ts), massError=worstMass)
    if ledger:
        figures.update(removed=removedTotal, ledgerRows=ledgerRows)
    check("every written cloud (%d) holds the seeded %d points%s, each id once" %
          (len(ts), nSeed, " + injected - removed (the open boundaries' ledger at %d times)" % ledgerRows
           if ledger else " minus %d removed" % a.removed if a.removed else ""),
          worstCount == 0 and dupes == 0 and len(ids0) == nSeed and (not ledger or ledgerRows > 0),
          "count off by %d, duplicates %d" % (worstCount, dupes))
    check("each point keeps its seeded mass; total mass = seeded%s" % (" + injected - removed" if ledger else ""),
          worstPoint <= 1e-14 and worstMass <= 1e-12 and abs(m0.sum()/mSeed - 1) <= 1e-5,
          "point %.3g, total %.3g (seeded %g)" % (worstPoint, worstMass, mSeed))

    # ---- energy --------------------------------------------------------------
    if a.energy_growth is not None:
        s = mpmPost.read_summary(c)
        pe = s.get("potentialEnergy", np.zeros_like(s["time"]))
        E = s["kineticEnergy"] + s["elasticEnergy"] + pe
        avail = E[0] - pe.min()
        growth = (E - E[0]).max()
        figures.update(energyAvailable=avail, energyGrowth=growth,
                       energyDrift=growth/avail if avail > 0 else 0.0,
                       energyFinal=(E[-1] - E[0])/avail if avail > 0 else 0.0)
        check("kinetic + stored + potential energy grows by <= %g of the available %.4g + source %g"
              % (a.energy_growth, avail, a.energy_source),
              bool(np.isfinite(E).all()) and growth <= a.energy_growth*avail + a.energy_source,
              "max growth %.4g = %.4g of available, over %d logged steps" % (growth, growth/avail if avail > 0 else 0, len(E)))
        if a.energy_window:
            # The trend, free of the in-period swing of a staggered measure:
            # mean energy over the first and the last window (a period)
            t = s["time"]
            first = E[t <= t[0] + a.energy_window].mean()
            last = E[t >= t[-1] - a.energy_window].mean()
            figures.update(energyTrend=(last - first)/avail)
            check("mean energy over the last window %g <= over the first" % a.energy_window,
                  last <= first, "trend %.4g of available" % ((last - first)/avail))

    # ---- volume fraction -----------------------------------------------------
    if a.alpha_max is not None:
        seen, raw, n = 0.0, 0.0, 0
        for t in timeDirs(c):
            if os.path.exists(os.path.join(c, t, "alpha.fluid")):
                seen = max(seen, 1 - mpmPost.read_internal_field(c, t, "alpha.fluid").min())
                n += 1
            if os.path.exists(os.path.join(c, t, "alpha.solid")):
                raw = max(raw, mpmPost.read_internal_field(c, t, "alpha.solid").max())
        caps = len(re.findall(rb"capped", log))
        figures.update(alphaSolidSeen=seen, alphaSolidRaw=raw, capLines=caps)
        check("1 - alpha.fluid <= alphaMax %g in every written field (%d)" % (a.alpha_max, n),
              n > 0 and seen <= a.alpha_max + 1e-12,
              "max %.6g; raw lattice alpha.solid max %.4g; log lines with caps %d" % (seen, raw, caps))

    print("figures: " + " ".join("%s=%.6g" % (k, v) if isinstance(v, float) else "%s=%s" % (k, v)
                                 for k, v in figures.items()))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
