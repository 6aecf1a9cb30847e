#!/usr/bin/env python3
"""Axial bar: centre-of-mass velocity against the exact first-mode solution
v_cm(t) = (2 V0 / pi) cos(w1 t),  w1 = (pi / 2L) sqrt(E / rho).

Prints the largest error relative to the amplitude 2 V0 / pi and writes
axialBar.png. Usage: plotAxialBar.py [case] [--no-plot]
"""
import os
import re
import sys

import numpy as np

import mpmPost

L, E, RHO, V0 = 25.0, 100.0, 1.0, 0.1


def amplitude(case):
    """V0 of the case's initial velocity (mpmSetParticlesDict amplitude)."""
    text = open(os.path.join(case, "system", "mpmSetParticlesDict")).read()
    return float(re.search(r"amplitude\s*\(\s*(\S+)", text).group(1))


def exact_vcm(t):
    w1 = np.pi/(2*L)*np.sqrt(E/RHO)
    return 2*V0/np.pi*np.cos(w1*t)


def fit_frequency(t, v, w_guess):
    """Least-squares fit of v = a cos(w t) + b sin(w t): returns w. The
    residual is scanned around the guess, then refined by golden section."""
    def residual(w):
        A = np.c_[np.cos(w*t), np.sin(w*t)]
        c = np.linalg.lstsq(A, v, rcond=None)[0]
        return np.sum((A @ c - v)**2)
    ws = np.linspace(0.95*w_guess, 1.05*w_guess, 401)
    k = int(np.argmin([residual(w) for w in ws]))
    lo, hi = ws[max(k - 1, 0)], ws[min(k + 1, len(ws) - 1)]
    g = (np.sqrt(5) - 1)/2
    for _ in range(60):
        a, b = hi - g*(hi - lo), lo + g*(hi - lo)
        if residual(a) < residual(b):
            hi = b
        else:
            lo = a
    return 0.5*(lo + hi)


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    case = args[0] if args else "."
    global V0
    V0 = amplitude(case)
    s = mpmPost.read_summary(case)
    t, v = s["time"], s["Ux"]
    amp = 2*V0/np.pi
    err = np.abs(v - exact_vcm(t))/amp
    print(f"axialBar: t = {t[0]:g} .. {t[-1]:g}, {len(t)} samples")
    print(f"axialBar: max |v_cm - exact| / (2 V0/pi) = {err.max():.6e}")
    print(f"axialBar: rms |v_cm - exact| / (2 V0/pi) = {np.sqrt(np.mean(err**2)):.6e}")
    w1 = np.pi/(2*L)*np.sqrt(E/RHO)
    w = fit_frequency(t, v, w1)
    print(f"axialBar: fitted w1 = {w:.8f}, exact {w1:.8f}, relative frequency error = {w/w1 - 1:.6e}")
    if "--no-plot" in sys.argv:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    tt = np.linspace(t[0], t[-1], 1000)
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(tt, exact_vcm(tt), "k-", label="exact $(2V_0/\\pi)\\cos\\omega_1 t$")
    ax.plot(t, v, "o", ms=3, mfc="none", label="mpmFoam")
    ax.set_xlabel("t")
    ax.set_ylabel("centre-of-mass velocity")
    ax.set_title(f"Axial bar: max error {100*err.max():.3f} % of amplitude")
    ax.legend()
    fig.tight_layout()
    fig.savefig("axialBar.png", dpi=120)
    print("axialBar: wrote axialBar.png")


if __name__ == "__main__":
    main()
