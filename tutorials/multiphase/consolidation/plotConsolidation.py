#!/usr/bin/env python3
"""consolidation: excess pore pressure against Terzaghi's 1D theory.

A saturated soil layer of depth H on an impermeable base, drained at the
top, starts unstressed under its own buoyant weight gamma' = aS (rho_s -
rho_f) g. The mixture is incompressible, so the weight is first carried by
an excess pore pressure u0 = gamma' (H - y); it drains through the top as

    du/dt = c_v d2u/dy2,   c_v = aF^2 M / beta   (Darcy: k/mu = aF^2/beta)

with M the skeleton's constrained modulus and beta the drag coefficient
(Ergun at Re -> 0: 150 aS^2 mu/(aF d^2)). With the depth z = H - y and
T = c_v t/H^2 (Terzaghi 1925; e.g. Verruijt, Soil Mechanics, ch. 15):

    u(z, T) = sum_m 2 gamma' H (-1)^m / M_m^2 sin(M_m z/H) exp(-M_m^2 T),
    M_m = pi (2m + 1)/2

Measured: u = rho_f (p - |g| (Hc - y)) at the cell centres (p kinematic,
p = 0 at the top of the column of height Hc). Compared inside the layer
(cells whose stencil does not reach its smeared top edge, y < H - 2h):

  * profiles at T = 0.05, 0.1, 0.2, 0.5, 1: max |u - u_T| / (gamma' H);
  * the degree of consolidation U(T) = 1 - int u dy / int u0 dy, with the
    analytic profile integrated over the same cells, at every write;
  * at the end, Terzaghi's principle in the skeleton: the points' effective
    stress sigma'_yy = -gamma' (H - y) + u (measured u), max error / gamma' H.

Prints the figures and a SUMMARY line; writes consolidation.png unless
--no-plot.
"""
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("MPMFOAM_DIR", ""), "etc", "python"))
import mpmPost  # noqa: E402

entry = mpmPost.dict_scalar


def setup(case):
    c = {}
    tp = os.path.join(case, "constant/transportProperties")
    c["rhoF"], c["nu"] = entry(tp, "rho"), entry(tp, "nu")
    c["mu"] = c["rhoF"]*c["nu"]
    mp = os.path.join(case, "constant/mpmProperties")
    c["rhoS"], c["E"], c["poisson"] = entry(mp, "rho"), entry(mp, "E"), entry(mp, "nu")
    c["d"] = float(re.search(r"drag\s*\{[^}]*\bd\s+([-+0-9.eE]+)", open(mp).read()).group(1))
    sp = os.path.join(case, "system/mpmSetParticlesDict")
    c["aS"] = entry(sp, "solidFraction")
    c["H"] = float(re.search(r"max\s*\(\s*\S+\s+(\S+)\s+\S+\s*\)", open(sp).read()).group(1))
    bm = os.path.join(case, "system/blockMeshDict")
    c["Hc"], c["h"] = entry(bm, "height"), entry(bm, "h")
    g = re.search(r"value\s+\(\s*\S+\s+(\S+)\s+\S+\s*\)", open(os.path.join(case, "constant/g")).read())
    c["g"] = abs(float(g.group(1)))
    E, nu, aS = c["E"], c["poisson"], c["aS"]
    aF = 1 - aS
    c["M"] = E*(1 - nu)/((1 + nu)*(1 - 2*nu))
    c["beta"] = 150*aS**2*c["mu"]/(aF*c["d"]**2)
    c["cv"] = aF**2*c["M"]/c["beta"]
    c["gammaP"] = aS*(c["rhoS"] - c["rhoF"])*c["g"]
    return c


def terzaghi(c, y, T, terms=400):
    """Excess pore pressure at heights y (depth z = H - y) and time factor T."""
    z = c["H"] - np.asarray(y, float)
    u = np.zeros_like(z)
    for m in range(terms):
        Mm = np.pi*(2*m + 1)/2
        u += 2*c["gammaP"]*c["H"]*(-1)**m/Mm**2*np.sin(Mm*z/c["H"])*np.exp(-Mm**2*T)
    return np.where(z >= 0, u, 0.0)


def main():
    args = mpmPost.plot_parser().parse_args()
    case = args.case
    c = setup(case)
    H, h, gH = c["H"], c["h"], c["gammaP"]*c["H"]
    print("consolidation: H = %g m, aS = %g, M = %.4g Pa, beta = %.4g kg/(m^3 s), c_v = %.4g m^2/s, "
          "H^2/c_v = %.4g s, gamma' H = %.2f Pa" % (H, c["aS"], c["M"], c["beta"], c["cv"], H**2/c["cv"], gH))

    times = [t for t in mpmPost.field_times(case, "p") if float(t) > 0]
    y = None
    rows = []          # (t, T, U measured, U analytic)
    profiles = {}
    for t in times:
        p = mpmPost.read_internal_field(case, t, "p")
        if y is None:
            y = (np.arange(len(p)) + 0.5)*h
            inner = y < H - 2*h
        u = c["rhoF"]*(p - c["g"]*(c["Hc"] - y))
        T = c["cv"]*float(t)/H**2
        ua = terzaghi(c, y, T)
        u0 = terzaghi(c, y, 0.0)
        Um = 1 - u[inner].sum()/u0[inner].sum()
        Ua = 1 - ua[inner].sum()/u0[inner].sum()
        rows.append((float(t), T, Um, Ua))
        profiles[t] = (T, u, ua)
    rows = np.array(rows)

    # profiles at the chosen time factors (nearest write)
    targets = [0.05, 0.1, 0.2, 0.5, 1.0]
    profErr = []
    print("%8s %8s %12s" % ("T", "t [s]", "max|u - u_T|/gamma'H"))
    for Tt in targets:
        t = min(profiles, key=lambda k: abs(profiles[k][0] - Tt))
        T, u, ua = profiles[t]
        e = np.abs(u - ua)[inner].max()/gH
        profErr.append(e)
        print("%8.3f %8s %12.4e" % (T, t, e))
    UErr = np.abs(rows[:, 2] - rows[:, 3]).max()
    print("degree of consolidation: max |U - U_T| over %d writes = %.4e" % (len(rows), UErr))
    for Tt in (0.1, 0.2, 0.5, 1.0):
        i = int(np.argmin(np.abs(rows[:, 1] - Tt)))
        print("  T = %.3f: U = %.4f (Terzaghi %.4f)" % (rows[i, 1], rows[i, 2], rows[i, 3]))

    # Terzaghi's principle in the skeleton at the end
    last = times[-1]
    xp = mpmPost.read_positions(case, last)[:, 1]
    sig = mpmPost.read_cloud_field(case, last, "stress")
    syy = sig[:, 3]                        # symmTensor (xx xy xz yy yz zz)
    _, uLast, _ = profiles[last]
    uAtPoints = np.interp(xp, y, uLast)
    expected = -c["gammaP"]*(H - xp) + uAtPoints
    deep = xp < H - 3*h
    stressErr = np.abs(syy - expected)[deep].max()/gH
    print("effective stress at t = %s (T = %.2f): max |sigma'_yy + gamma'(H - y) - u| / gamma'H = %.4e "
          "(%d points below H - 3h)" % (last, rows[-1, 1], stressErr, int(deep.sum())))
    print("SUMMARY profileErrMax=%.6g UErrMax=%.6g stressErr=%.6g Tend=%.6g cv=%.6g"
          % (max(profErr), UErr, stressErr, rows[-1, 1], c["cv"]))

    if args.no_plot:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.5))
    yf = np.linspace(0, H, 200)
    for k, Tt in enumerate(targets):
        t = min(profiles, key=lambda key: abs(profiles[key][0] - Tt))
        T, u, ua = profiles[t]
        ax.plot(terzaghi(c, yf, T)/gH, yf/H, "-", color="C%d" % k, lw=1)
        ax.plot(u/gH, y/H, "o", color="C%d" % k, ms=3, label="T = %.2f" % T)
    ax.plot([], [], "k-", lw=1, label="Terzaghi")
    ax.set_xlabel("excess pore pressure u / (gamma' H)")
    ax.set_ylabel("y / H")
    ax.set_ylim(0, c["Hc"]/H)
    ax.legend(fontsize=8)
    ax.set_title("consolidation: pore pressure profiles")
    bx.plot(rows[:, 1], rows[:, 3], "k-", lw=1, label="Terzaghi")
    bx.plot(rows[:, 1], rows[:, 2], "o", ms=3, label="mpmFoam")
    bx.set_xscale("log")
    bx.set_xlabel("T = c_v t / H^2")
    bx.set_ylabel("degree of consolidation U")
    bx.invert_yaxis()
    bx.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(case, "consolidation.png"), dpi=120)
    print("wrote consolidation.png")


if __name__ == "__main__":
    main()
