#!/usr/bin/env python3
"""The coupled spectral analysis against an mpmFoam run of one Fourier mode.

The case (coupledModeCase) is the analysis' setting: a periodic 1D column,
frozen stress-free grains at uniform alpha.solid, still water, linear drag,
no gravity, one sine mode of the grains' velocity. The analysis gives the
amplification matrix A of one fluid step (mpmStabilityAnalysis --model
coupled --symbol kh) on the state x = (v_p per point offset, U, phi, p),
in lattice units (h = Dt = 1). The run's Fourier coefficients of every
state component are read at every fluid step and compared:

* one step: A x_n (x_n measured, phi included) against x_{n+1}: the
  per-step map, v, U, phi and p;
* the per-step amplification of the grains' mode g_n = <v_n, v_{n+1}>/|v_n|^2
  against the same of A x_n;
* the whole history A^n x_0 from the measured start (fluid at rest).

OpenFOAM's Euler ddtCorr multiplies its correction by 1 - min(|phiCorr|/|phi|,
1) per face: scale-free but not linear. The analysis takes 1. From rest
(phiCorr = 0) the first step is exact; later steps differ by ~|phiCorr/phi|
times the correction, sin^2(kh/2)-small: the history accumulates it in the
ddtCorr mode, the one-step comparison does not.

The ddtCorr coefficient changes the cell velocity and the pressure of a step
by ~|phiCorr/phi| (6e-4 at kh = 2 pi/128) of the correction, but not the
face flux, whence the grains' drag and the amplification: --fluid-tol.

Usage: compareWithAnalysis.py <case> <tool> [--tol 1e-6] [--fluid-tol 1e-5]
       [--cutoff 1e-6] [--variant linearised|frozen (default: the case's fluidResponse)]
Steps are compared while the mode is above cutoff of its start. Exits 1 if
a one-step difference exceeds its tolerance (tol: g, v, phi; fluid-tol: U, p).
"""
import os
import re
import subprocess
import sys

import numpy as np

import mpmPost


def value(path, key):
    with open(path) as f:
        text = re.sub(r"//.*", "", f.read())
    m = re.search(r"(?m)^\s*" + key + r"\s+([^;]+);", text)
    if m is None:
        raise KeyError(f"{key} in {path}")
    return m.group(1).strip()


def option(name, default):
    return sys.argv[sys.argv.index(name) + 1] if name in sys.argv else default


def face_flux(case, time, area):
    """phi on the faces y = (i + 1) h, i = 0..n-1 (the last one the cyclic
    face), divided by the face area."""
    with open(os.path.join(case, time, "phi")) as f:
        text = f.read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\((.*?)\n\)", text, re.S)
    inner = np.array([float(v) for v in m.group(2).split()])
    cyc = float(re.search(r"high\s*\{[^}]*?value\s+uniform\s+(\S+);", text, re.S).group(1))
    return np.r_[inner, cyc]/area


def main():
    case, tool = sys.argv[1], sys.argv[2]
    tol = float(option("--tol", 1e-6))
    fluid_tol = float(option("--fluid-tol", 1e-5))
    cutoff = float(option("--cutoff", 1e-6))
    try:    # the solver's fluidResponse (an analysis aid) is the variant
        variant = value(os.path.join(case, "constant", "mpmProperties"), "fluidResponse")
    except KeyError:
        variant = "linearised"
    variant = option("--variant", variant)
    mpm = os.path.join(case, "constant", "mpmProperties")
    shape = {"linearHat": "LH", "quadraticBSpline": "QBS", "cubicBSpline": "CBS"}[value(mpm, "shapeFunction")]
    alpha = float(value(mpm, "flipRatio"))
    mode = value(mpm, "mode")
    forces = value(mpm, "forces").strip("()").split()
    n_sub = int(value(mpm, "subCycles"))
    rho_s = float(value(mpm, "rho"))
    d = float(re.search(r"Ergun;\s*d\s+([^;]+);", open(mpm).read()).group(1))
    tp = os.path.join(case, "constant", "transportProperties")
    nu, rho_f = float(value(tp, "nu")), float(value(tp, "rho"))
    dt = float(value(os.path.join(case, "system", "controlDict"), "deltaT"))
    mesh = os.path.join(case, "system", "blockMeshDict")
    h = float(value(mesh, "h"))
    n_cells = int(value(mesh, "nCells"))
    piso = int(value(os.path.join(case, "system", "fvSolution"), "nCorrectors"))

    times = mpmPost.times(case)
    y = mpmPost.read_positions(case, times[0])[:, 1]
    k = 2*np.pi/(n_cells*h)
    kh = k*h
    # Lattice coordinate: nodes at the cell centres (node j at y = (j + 1/2) h)
    off = np.round(np.mod((y - 0.5*h)/h, 1.0), 9) % 1.0
    offsets = sorted(set(off))
    classes = [np.where(off == o)[0] for o in offsets]
    yc = (np.arange(n_cells) + 0.5)*h
    yf = (np.arange(n_cells) + 1.0)*h

    a_s = float(np.mean(mpmPost.read_internal_field(case, times[1], "alpha.solid")))
    a_f = 1 - a_s
    # The drag law at zero slip (Ergun, src/mpmCore/drag/dragLaws.hpp): the
    # solver's beta differs by the slip term, ~1e-8 relative at this amplitude
    beta = 150*a_s**2*rho_f*nu/(a_f*d*d)
    tau = a_s*rho_s/beta
    args = [tool, "--model", "coupled", "--solid", "diffusion", "--number", "0",
            "--shape", shape, "--alpha", repr(alpha), "--offsets", ",".join(repr(float(o)) for o in offsets),
            "--mode", mode, "--variant", variant, "--forces", ",".join(f for f in forces if f != "gravity"),
            "--aS", repr(a_s), "--density-ratio", repr(rho_f/rho_s), "--sub-cycles", str(n_sub),
            "--dt-tau", repr(dt/tau), "--viscous", repr(nu*dt/h**2), "--correctors", str(piso),
            "--symbol", repr(kh)]
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    rows = [r.split() for r in out.splitlines() if r and not r.startswith("#")]
    A = np.array([[complex(float(a), float(b)) for a, b in zip(r[0::2], r[1::2])] for r in rows])
    npc = len(offsets)
    iU, iPhi, iP = npc, npc + 1, npc + 2

    # Lattice units: velocities in h/Dt, the kinematic pressure in (h/Dt)^2
    vel = h/dt

    def coeff(values, pos):
        return 2.0/len(values)*np.sum(values*np.exp(-1j*k*(pos - 0.5*h)))

    def state(t):
        v = mpmPost.read_cloud_field(case, t, "U")[:, 1]/vel
        x = np.zeros(A.shape[0], complex)
        for l, c in enumerate(classes):
            x[l] = coeff(v[c], y[c])
        if t != times[0]:
            U = mpmPost.read_internal_field(case, t, "U")
            p = mpmPost.read_internal_field(case, t, "p")
            if U.ndim == 2:     # else uniform: the fluid at rest (one-way)
                x[iU] = coeff(U[:, 1]/vel, yc)
                x[iPhi] = coeff(face_flux(case, t, h*h)/vel, yf)
            if np.ndim(p) == 1:
                x[iP] = coeff(p/vel**2, yc)
        return x

    def rel(a, b):
        return np.linalg.norm(a - b)/np.linalg.norm(b)

    def amplification(x0, x1):
        return np.vdot(x0[:npc], x1[:npc])/np.vdot(x0[:npc], x0[:npc])

    print(f"{mode} {variant}: kh {kh:.6g}, aS {a_s:.6g}, Dt/tau {dt/tau:.6g}, subCycles {n_sub}, "
          f"nu Dt/h^2 {nu*dt/h**2:.3g}, offsets {offsets}")
    print(" ".join(args))
    xs = [state(t) for t in times]
    v0 = np.linalg.norm(xs[0][:npc])
    worst = {"g": 0.0, "v": 0.0, "U": 0.0, "phi": 0.0, "p": 0.0}
    worst_history = 0.0
    hist = xs[0].copy()
    last = 0
    print(f"{'step':>4} {'|v|/|v0|':>10} {'g measured':>14} {'g analysis':>14} {'err g':>9} {'err v':>9} {'err U':>9}"
          f" {'err phi':>9} {'err p':>9} {'history v':>10}")
    for n in range(len(xs) - 1):
        x, x1 = xs[n], xs[n + 1]
        if np.linalg.norm(x1[:npc]) < cutoff*v0:
            break
        pred = A @ x
        hist = A @ hist
        g_m, g_a = amplification(x, x1), amplification(x, pred)
        # The fluid's differences relative to its own mode, or to the grains'
        # where the fluid's vanishes (no solid flux: twoWayMomentum, oneWay)
        vs = np.linalg.norm(pred[:npc])
        e = {"g": abs(g_m - g_a)/abs(g_a), "v": rel(x1[:npc], pred[:npc]),
             "U": abs(x1[iU] - pred[iU])/max(abs(pred[iU]), vs),
             "phi": abs(x1[iPhi] - pred[iPhi])/max(abs(pred[iPhi]), vs),
             "p": abs(x1[iP] - pred[iP])/max(abs(pred[iP]), 1e-300)}
        eh = rel(x1[:npc], hist[:npc])
        for key in worst:
            worst[key] = max(worst[key], e[key])
        worst_history = max(worst_history, eh)
        print(f"{n + 1:4d} {np.linalg.norm(x1[:npc])/v0:10.3e} {g_m.real:+14.10f} {g_a.real:+14.10f} {e['g']:9.2e}"
              f" {e['v']:9.2e} {e['U']:9.2e} {e['phi']:9.2e} {e['p']:9.2e} {eh:10.2e}")
        last = n + 1
    ev = np.linalg.eigvals(A)
    lead = ev[np.argmax(abs(ev))]
    print(f"dominant eigenvalue {lead.real:+.10f} {lead.imag:+.3e} last amplification {g_m.real:+.10f}")
    print(f"growth over {last} steps: measured {np.linalg.norm(xs[last][:npc])/v0:.10g}, "
          f"analysis {np.linalg.norm((np.linalg.matrix_power(A, last) @ xs[0])[:npc])/v0:.10g}")
    print("largest one-step relative differences: " + ", ".join(f"{k} {v:.2e}" for k, v in worst.items())
          + f"; history (A^n x0) v {worst_history:.2e}")
    ok = all(worst[k] <= tol for k in ("g", "v", "phi")) and all(worst[k] <= fluid_tol for k in ("U", "p"))
    print(("PASS" if ok else "FAIL") + f": one-step amplification, grain mode and flux within {tol:g},"
          f" fluid U and p within {fluid_tol:g}")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
