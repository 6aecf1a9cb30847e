#!/usr/bin/env python3
"""Write the hydrostatic initial pressure p = |g| (height - y) (kinematic)
into 0/p for the column's current blockMeshDict (height, nCells): the
grains' first step then sees the buoyancy. Used when the column is
resized (tests/cases/consolidation.sh, the accuracy-cost sweep)."""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ.get("MPMFOAM_DIR", ""), "etc", "python"))
import mpmPost  # noqa: E402

case = sys.argv[1] if len(sys.argv) > 1 else "."
bm = os.path.join(case, "system", "blockMeshDict")
height, n = mpmPost.dict_scalar(bm, "height"), int(mpmPost.dict_scalar(bm, "nCells"))
g = abs(float(re.search(r"value\s+\(\s*\S+\s+(\S+)\s+\S+\s*\)",
                        open(os.path.join(case, "constant", "g")).read()).group(1)))
h = height/n
vals = "\n".join("%.6g" % (g*(height - (i + 0.5)*h)) for i in range(n))
path = os.path.join(case, "0", "p")
text = re.sub(r"internalField\s+nonuniform\s+List<scalar>\s+\d+\s*\([^)]*\)",
              "internalField   nonuniform List<scalar> %d\n(\n%s\n)" % (n, vals), open(path).read())
open(path, "w").write(text)
