"""Post-processing helpers for mpmFoam cases (numpy only; plots use matplotlib).

Reads the solver's postProcessing/mpmSummary/*/summary.dat and the ASCII
lagrangian fields of the materialPoints cloud.
"""
import argparse
import glob
import os
import re

import numpy as np


def read_summary(case="."):
    """Rows of every summary.dat of the case, sorted by time, duplicates
    (restarts) resolved in favour of the later run."""
    rows = []
    for f in sorted(glob.glob(os.path.join(case, "postProcessing", "mpmSummary", "*", "summary.dat")),
                    key=lambda p: float(os.path.basename(os.path.dirname(p)))):
        d = np.loadtxt(f, comments="#", ndmin=2)
        if rows:
            rows = [r[r[:, 0] < d[0, 0]] for r in rows]
        rows.append(d)
    data = np.vstack(rows)
    names = ["time", "kineticEnergy", "elasticEnergy", "Ux", "Uy", "Uz", "maxU", "potentialEnergy"]
    return {n: data[:, i] for i, n in enumerate(names) if i < data.shape[1]}


def read_open_boundary(case=".", name="massBalance"):
    """Columns of postProcessing/openBoundaries/*/<name>.dat: an open patch's
    flux table (name: the patch) or the mass balance (massBalance), named by
    the file's header, restarts resolved in favour of the later run."""
    rows, names = [], None
    for f in sorted(glob.glob(os.path.join(case, "postProcessing", "openBoundaries", "*", name + ".dat")),
                    key=lambda p: float(os.path.basename(os.path.dirname(p)))):
        with open(f) as fh:
            header = [l for l in fh if l.startswith("# time")]
        names = header[-1][1:].split()
        d = np.loadtxt(f, comments="#", ndmin=2)
        if rows:
            rows = [r[r[:, 0] < d[0, 0]] for r in rows]
        rows.append(d)
    if names is None:
        raise FileNotFoundError("no postProcessing/openBoundaries/*/%s.dat in %s" % (name, case))
    data = np.vstack(rows)
    return {n: data[:, i] for i, n in enumerate(names)}


def _time_dirs(case, has):
    """Time directories (strings, ascending) for which has(path) is true."""
    out = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if has(os.path.join(case, d)):
            out.append((t, d))
    return [d for _, d in sorted(out)]


def times(case="."):
    """Write times that hold a materialPoints cloud, ascending."""
    return _time_dirs(case, lambda p: os.path.isdir(os.path.join(p, "lagrangian", "materialPoints")))


_number = r"[-+0-9.eEinfINFnaN]+"


def read_cloud_field(case, time, name):
    """An ASCII IOField of the materialPoints cloud as a numpy array
    (n,) for scalars/labels, (n, k) for vectors and tensors."""
    path = os.path.join(case, time, "lagrangian", "materialPoints", name)
    with open(path) as f:
        text = f.read()
    body = text[text.index("}", text.index("FoamFile")) + 1:]
    body = re.sub(r"//.*", "", body)
    m = re.search(r"(\d+)\s*\(", body)
    if m is None:
        # uniform list: N{value}
        m = re.search(r"(\d+)\s*\{\s*(.*?)\s*\}", body, re.S)
        n = int(m.group(1))
        vals = [float(x) for x in re.findall(_number, m.group(2))]
        return np.tile(vals, (n, 1)).squeeze()
    n = int(m.group(1))
    inner = body[m.end():body.rindex(")")]
    vals = np.array([float(x) for x in re.findall(_number, inner)])
    if n == 0:
        return vals
    return vals.reshape(n, -1).squeeze() if vals.size != n else vals


def read_positions(case, time):
    """Point positions (n, 3) from the 'positions' file (x y z celli)."""
    path = os.path.join(case, time, "lagrangian", "materialPoints", "positions")
    with open(path) as f:
        text = f.read()
    body = text[text.index("}", text.index("FoamFile")) + 1:]
    rows = re.findall(r"\(\s*(" + _number + r")\s+(" + _number + r")\s+(" + _number + r")\s*\)", body)
    return np.array([[float(a), float(b), float(c)] for a, b, c in rows])


def read_internal_field(case, time, name):
    """internalField of an ASCII volField as a numpy array ((n,) or (n, 3)),
    a uniform value repeated n times when n is given by a neighbour field."""
    path = os.path.join(case, time, name)
    with open(path) as f:
        text = f.read()
    m = re.search(r"internalField\s+nonuniform\s+List<\w+>\s*(\d+)\s*\((.*?)\n\)\s*;", text, re.S)
    if m:
        n = int(m.group(1))
        vals = np.array([float(x) for x in re.findall(_number, m.group(2))])
        return vals.reshape(n, -1).squeeze()
    m = re.search(r"internalField\s+uniform\s+(\(.*?\)|\S+);", text)
    vals = [float(x) for x in re.findall(_number, m.group(1))]
    return np.array(vals if len(vals) > 1 else vals[0])


def field_times(case, name):
    """Time directories (strings, ascending) holding field `name`."""
    return _time_dirs(case, lambda p: os.path.isfile(os.path.join(p, name)))


def dict_scalar(path, key):
    """First scalar value of `key` in an OpenFOAM dictionary file (comments
    stripped; the keyword may sit in any sub-dictionary)."""
    text = re.sub(r"//.*", "", open(path).read())
    m = re.search(r"(?<![\w.])" + re.escape(key) + r"\s+([-+0-9.eE]+)\s*;", text)
    if m is None:
        raise KeyError("%s not found in %s" % (key, path))
    return float(m.group(1))


def write_stl(path, triangles, name="surface"):
    """Writes triangles, a sequence of three (x, y, z) corners each, as an
    ASCII STL solid called name. The facet normals are left zero: OpenFOAM
    takes the orientation from the corners' order (counter-clockwise seen
    from the side the normal points to)."""
    with open(path, "w") as f:
        f.write("solid %s\n" % name)
        for t in triangles:
            f.write(" facet normal 0 0 0\n  outer loop\n")
            for v in t:
                f.write("   vertex %.10g %.10g %.10g\n" % tuple(v))
            f.write("  endloop\n endfacet\n")
        f.write("endsolid %s\n" % name)


def plot_parser(description=None):
    """Command line of the tutorials' plot scripts: --case (default '.') and
    --no-plot (print the figures only); add a script's own options to it."""
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("--case", default=".")
    ap.add_argument("--no-plot", action="store_true")
    return ap


def richardson(values, ratio=2.0):
    """Richardson extrapolation of one result from grids refined by a
    constant ratio, with Roache's grid convergence index as its error band.

    values: the result on each grid, coarsest first (at least three). The
    last three give the observed order p = ln(e_coarse/e_fine)/ln(ratio),
    where e_coarse and e_fine are the changes over the two refinements, and
    the limit f_fine + e_fine/(ratio^p - 1). The band is f_fine +- GCI with
    GCI = Fs |limit - f_fine|: Fs = 1.25 when p lies in [0.5, 2.5] (three
    grids that confirm an order), otherwise 3 (Roache 1998, ch. 5: an order
    the grids do not confirm is not trusted). With four or more values the
    order of the previous three is returned too (p_previous): an order that
    moves between the triples says the grids are not yet asymptotic.

    Returns a dict: status ('converging', 'oscillating' or 'diverging'),
    previous_status and p_previous (the coarser triple's; None with three
    values), and, when converging, p, limit, gci, fs and band (lo, hi). Oscillating or diverging changes have no
    extrapolation: the caller says so instead of printing a number.
    """
    f = [float(v) for v in values]
    if len(f) < 3:
        raise ValueError("richardson: needs at least three grids, got %d" % len(f))

    def order(f1, f2, f3):
        e21, e32 = f2 - f1, f3 - f2
        if e21*e32 <= 0:
            return "oscillating", None
        if abs(e32) >= abs(e21):
            return "diverging", None
        return "converging", np.log(e21/e32)/np.log(ratio)

    status, p = order(*f[-3:])
    result = {"status": status, "p_previous": None, "previous_status": None}
    if len(f) >= 4:
        result["previous_status"], result["p_previous"] = order(*f[-4:-1])
    if status != "converging":
        return result
    limit = f[-1] + (f[-1] - f[-2])/(ratio**p - 1)
    fs = 1.25 if 0.5 <= p <= 2.5 else 3.0
    gci = fs*abs(limit - f[-1])
    result.update(p=p, limit=limit, fs=fs, gci=gci, band=(f[-1] - gci, f[-1] + gci))
    return result


def richardson_line(values, ratio=2.0, fmt="%.3f"):
    """One line saying what richardson() found, for the tutorials' tables."""
    r = richardson(values, ratio)
    if r["status"] != "converging":
        return "%s over the last three grids: no extrapolation" % r["status"]
    line = ("observed order p = %.2f, Richardson limit " + fmt + ", band " + fmt + " .. " + fmt
            + " (GCI, Fs = %g)") % (r["p"], r["limit"], r["band"][0], r["band"][1], r["fs"])
    if r["p_previous"] is not None:
        line += "; the coarser triple gives p = %.2f" % r["p_previous"]
    elif r["previous_status"] is not None:
        line += "; the coarser triple is %s" % r["previous_status"]
    return line
