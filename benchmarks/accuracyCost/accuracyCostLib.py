"""Shared helpers of the accuracy-cost benchmark (run.py, budget.py):
results CSV reading, configuration labels and the Pareto front."""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "etc", "python"))
import accuracyCost  # noqa: E402

# Columns of results.csv, in order.
COLUMNS = [
    "set", "shape", "alpha", "mass", "ppc", "cells", "cflFraction",
    "limitBasis", "analysedLimitConsistent", "cfl", "dt", "steps", "points",
    "nodeCrossing", "status", "failure", "maxURatio", "vcmMaxError", "vcmRmsError", "L2Error",
    "vcmCentredError",
    "solverTime", "p2gTime", "nodalTime", "g2pTime", "constitutiveTime", "ioTime",
    "wallTime", "secPerPointStep",
]

METRICS = {"vcm": "vcmMaxError", "vcmc": "vcmCentredError", "L2": "L2Error"}
TIMES = {"solver": "solverTime", "wall": "wallTime"}

_INT = {"ppc", "cells", "steps", "points", "nodeCrossing"}
_STR = {"set", "shape", "mass", "status", "failure"}


def read_results(path):
    """Rows of results.csv as dicts with numbers converted; '#' lines are
    the machine header and are returned separately."""
    header, lines = [], []
    with open(path) as f:
        for line in f:
            (header if line.startswith("#") else lines).append(line)
    rows = []
    for r in csv.DictReader(lines):
        for k, v in r.items():
            if k in _STR:
                continue
            if k in _INT:
                r[k] = int(v) if v not in ("", None) else None
            else:
                r[k] = float(v) if v not in ("", None) else math.nan
        rows.append(r)
    return header, rows


def label(r, short=False):
    """Human-readable configuration of a row."""
    mass = "cons" if r["mass"] == "consistent" else "lump"
    if short:
        return (f"{r['shape']} a{r['alpha']:g} {mass} {r['ppc']}ppc "
                f"n{r['cells']} {r['cflFraction']:g}L")
    return (f"{r['shape']}, alpha {r['alpha']:g}, {r['mass']} mass, "
            f"{r['ppc']} ppc, {r['cells']} cells, CFL {r['cfl']:.3f} "
            f"({r['cflFraction']:g} x limit {r['limitBasis']:.3f})")


def usable(r):
    """Stable grid/consistent runs (probes beyond the analysed limit are
    reported but never recommended)."""
    return r["status"] == "ok" and r["set"] != "probe"


# The Pareto front has one home, shared with bin/mpmAccuracyCost
pareto = accuracyCost.pareto
