#!/usr/bin/env python3
"""Geostatic initial stress of the seeded column (0/lagrangian/materialPoints/stress).

The column is seeded stress-free, so under gravity it first drops and rings
elastically, by strains ~ rho g h0/E that depend on the (soft) E. This
writes the at-rest state of a layer of the column's height instead:

    sigma_yy = -rho g (h0 - y),   sigma_xx = sigma_zz = K0 sigma_yy

with rho = mass/volume of each point, g from constant/g and h0 the top of
the points (centre + half the point spacing). K0 defaults to the elastic
nu/(1 - nu) of a laterally confined layer (nu from --nu, default 0.3), the
state of a column held by its gate before release.

Usage: setGeostaticStress.py [case] [--K0 K0] [--nu nu]
"""
import argparse
import os
import re

import numpy as np

import mpmPost


def gravity(case):
    with open(os.path.join(case, "constant", "g")) as f:
        m = re.search(r"value\s*\(\s*(\S+)\s+(\S+)\s+(\S+)\s*\)", f.read())
    return float(m.group(2))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("case", nargs="?", default=".")
    p.add_argument("--nu", type=float, default=0.3)
    p.add_argument("--K0", type=float, default=None)
    a = p.parse_args()
    K0 = a.K0 if a.K0 is not None else a.nu/(1 - a.nu)
    t = mpmPost.times(a.case)[0]
    x = mpmPost.read_positions(a.case, t)
    rho = mpmPost.read_cloud_field(a.case, t, "mass")/mpmPost.read_cloud_field(a.case, t, "volume")
    u = np.unique(np.round(x[:, 1], 10))
    dp = float(np.min(np.diff(u)))
    top = x[:, 1].max() + dp/2
    gy = gravity(a.case)          # negative: downwards
    syy = rho*gy*(top - x[:, 1])
    sxx = K0*syy
    path = os.path.join(a.case, t, "lagrangian", "materialPoints", "stress")
    with open(path) as f:
        text = f.read()
    head = text[:text.index("}", text.index("FoamFile")) + 1]
    # OpenFOAM symmTensor order: xx xy xz yy yz zz
    rows = "\n".join("(%.10g 0 0 %.10g 0 %.10g)" % (sx, sy, sx) for sx, sy in zip(sxx, syy))
    with open(path, "w") as f:
        f.write(head + "\n\n%d\n(\n%s\n)\n" % (len(x), rows))
    print("Geostatic stress of %d points: top %.4f m, K0 = %.4f, sigma_yy at the floor %.4g Pa"
          % (len(x), top, K0, syy.min()))


if __name__ == "__main__":
    main()
