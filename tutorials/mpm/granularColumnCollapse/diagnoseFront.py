#!/usr/bin/env python3
"""Where the column's runout stops converging: the same column at several cell
sizes, compared phase by phase.

For runs of ./sweepAspectRatio of one material and aspect ratio at
different h (sweep/<material>_a<a>_h<h>), prints three tables:

1. The failure wedge at t = 0.1 s: on the horizontal line y = h0/4, the speed
   of the sliding wedge and the width over which the speed rises from 10 %
   to 90 % of it (the failure zone). A width that shrinks with h (a constant
   number of cells) would be localisation at the grid scale; a width in
   metres that stays put is a resolved failure zone.
2. The spreading layer: the x-velocity averaged over eighths of the depth,
   base to surface, in the column x in [1.5 a0, 1.7 a0] at two times. A
   static base under a flowing top, and the thickness of the shear zone
   between them (u_x from 10 % to 90 % of the surface's, on 32 slices).
   A rate-independent (or low-I) law has no length of its own to set it.
3. The front: the 99.9 % mass front and the mean x-velocity of the last 1 %
   of the mass over time, and the tail's mean deceleration over the 0.25 s
   after its peak speed. A free layer on the floor decelerates at mu g.

The times (0.1, 0.45, 0.55 s) and the column x in [1.5, 1.7] a0 are chosen
for the tutorial's a = 2 column (at rest from t ~ 0.7 s).

Usage: diagnoseFront.py RUN...   (runs of one material and a, any h)
"""
import os
import re
import sys

import numpy as np

import mpmPost
from plotProfile import mass_front, mass_order, measure

G = 9.81


def floor_friction(run):
    """The floor's Coulomb coefficient from the run's constant/mpmProperties,
    None for a floor of another type (slip, noSlip)."""
    text = open(os.path.join(run, "constant", "mpmProperties")).read()
    m = re.search(r"floor\s*\{[^}]*type\s+friction\s*;[^}]*frictionCoefficient\s+([0-9.eE+-]+)", text)
    return float(m.group(1)) if m else None


def cell_size(run):
    return float(re.search(r"_h([0-9.]+)", os.path.basename(run.rstrip("/"))).group(1))


def nearest_time(run, t):
    ts = mpmPost.times(run)
    return min(ts, key=lambda s: abs(float(s) - t))


def wedge_and_width(x, u, y, h):
    """(wedge speed, 10-90 % width) of the points x, velocities u on the line
    y (within h/4): the wedge's speed is the 95th percentile of the speeds
    there, the width the distance from the first point faster than 10 % of
    it to the first faster than 90 %, in increasing x."""
    line = np.abs(x[:, 1] - y) < h/4 + 1e-9
    order = np.argsort(x[line, 0])
    xs = x[line, 0][order]
    speed = np.hypot(u[line, 0], u[line, 1])[order]
    wedge = np.percentile(speed, 95)
    return wedge, xs[np.argmax(speed > 0.9*wedge)] - xs[np.argmax(speed > 0.1*wedge)]


def failure_zone(run, t, y, h):
    """(wedge speed, 10-90 % width) on the line y at time t."""
    return wedge_and_width(mpmPost.read_positions(run, t), mpmPost.read_cloud_field(run, t, "U"), y, h)


def layer(run, t, x0, x1):
    """The points of the column x in [x0, x1) at time t: (depth, height over
    the depth, u_x)."""
    x = mpmPost.read_positions(run, t)
    u = mpmPost.read_cloud_field(run, t, "U")
    column = (x[:, 0] >= x0) & (x[:, 0] < x1)
    depth = x[column, 1].max()
    return depth, x[column, 1]/depth, u[column, 0]


def slice_means(height, ux, bins):
    """Mean u_x in each of `bins` equal slices of the depth, base up."""
    k = np.minimum((height*bins).astype(int), bins - 1)
    return np.array([ux[k == i].mean() if np.any(k == i) else np.nan for i in range(bins)])


def shear_zone(depth, ux):
    """Thickness over which u_x rises from 10 % to 90 % of the flowing top's
    speed, the profile taken as monotone from the base (its running
    maximum), so that the top's speed is its fastest slice even where the
    surface is a little slower than the flow just below it."""
    z = (np.arange(len(ux)) + 0.5)*depth/len(ux)
    rising = np.maximum.accumulate(np.nan_to_num(ux))
    top = rising[-1]
    return np.interp(0.9*top, rising, z) - np.interp(0.1*top, rising, z)


def front_history(run):
    """[(t, 99.9 % front, mean u_x of the last 1 % of the mass)]."""
    rows = []
    for t in mpmPost.times(run):
        x = mpmPost.read_positions(run, t)
        u = mpmPost.read_cloud_field(run, t, "U")
        m = mpmPost.read_cloud_field(run, t, "mass")
        ordered = mass_order(x, m)
        order, cumulative = ordered
        tail = order[cumulative > 0.99]
        rows.append((float(t), mass_front(x, m, ordered=ordered), u[tail, 0].mean()))
    return rows


def tail_deceleration(rows, window=0.25):
    """The tail's mean deceleration over `window` seconds after its peak
    speed, from front_history's rows: (peak row, end row, deceleration)."""
    peak = max(range(len(rows)), key=lambda i: rows[i][2])
    end = min(range(len(rows)), key=lambda i: abs(rows[i][0] - rows[peak][0] - window))
    return rows[peak], rows[end], (rows[peak][2] - rows[end][2])/(rows[end][0] - rows[peak][0])


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__.strip().splitlines()[-1])
    runs = sorted(sys.argv[1:], key=cell_size, reverse=True)
    geometry = {run: measure(run) for run in runs}
    a0, h0 = geometry[runs[0]]["a0"], geometry[runs[0]]["h0"]

    print("1. Failure wedge at t = 0.1 s on the line y = h0/4 = %.3f m" % (h0/4))
    print("   %-8s %12s %14s %8s" % ("h [m]", "wedge [m/s]", "10-90 % [m]", "cells"))
    for run in runs:
        h = cell_size(run)
        wedge, width = failure_zone(run, nearest_time(run, 0.1), h0/4, h)
        print("   %-8g %12.3f %14.4f %8.1f" % (h, wedge, width, width/h))

    x0, x1 = 1.5*a0, 1.7*a0
    for t in (0.45, 0.55):
        print("2. Spreading layer, x in [%.2f, %.2f] m, t = %g s: u_x [m/s] by eighths of the depth, base -> surface"
              % (x0, x1, t))
        for run in runs:
            depth, height, ux = layer(run, nearest_time(run, t), x0, x1)
            zone = shear_zone(depth, slice_means(height, ux, 32))
            print("   h %-7g depth %.4f m: %s | 10-90 %% shear zone %.4f m = %.1f cells"
                  % (cell_size(run), depth, " ".join("%6.3f" % v for v in slice_means(height, ux, 8)), zone,
                     zone/cell_size(run)))

    mu = floor_friction(runs[0])
    print("3. Front (99.9 %% of the mass) and the last 1 %% of the mass; %s"
          % ("the floor's mu g = %g g = %.2f m/s^2" % (mu, mu*G) if mu else "the floor is not a friction wall"))
    histories = {run: front_history(run) for run in runs}
    print("   %-6s" % "t [s]" + "".join("   h %-6g front  u_x" % cell_size(r) for r in runs))
    for i in range(len(histories[runs[0]])):
        print("   %-6g" % histories[runs[0]][i][0]
              + "".join("   %13.3f %5.2f" % histories[r][i][1:] for r in runs if i < len(histories[r])))
    # The tails reach their peak speed at the same time at every h; compare
    # their deceleration over the same window after it.
    for run in runs:
        peak, end, decel = tail_deceleration(histories[run])
        print("   h %-7g peak tail speed %.3f m/s at t = %g s (front %.3f m); deceleration to t = %g s: %.2f m/s^2"
              "%s; final runout (L - a0)/a0 = %.3f"
              % (cell_size(run), peak[2], peak[0], peak[1], end[0], decel,
                 " = %.2f mu g" % (decel/(mu*G)) if mu else "", (geometry[run]["Lf"] - a0)/a0))


if __name__ == "__main__":
    main()
