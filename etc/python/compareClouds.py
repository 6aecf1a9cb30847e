#!/usr/bin/env python3
"""Largest relative differences between the materialPoints clouds of two
runs at one time, matched by pointId. Each run is a case directory: its own
<time>/lagrangian (serial or reconstructed) or, with no such directory, its
processor*/<time>/lagrangian (decomposed, read as is), or else its HDF5
checkpoint HDF5/materialPoints_<time>.h5 (pointOutput hdf5; its symmetric
tensors are in OpenFOAM's order, so both formats compare directly).

    compareClouds.py CASE_A CASE_B TIME [--fields U stress ...]

Prints one line per field, "field maxRelDiff", where the difference is the
largest |a - b| over points and components divided by the largest |a| of
the field (positions: by the domain's extent seen in the cloud), then a
line "count nA nB" and "ids equal 0|1". Exit code 0.
"""
import argparse
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mpmPost  # noqa: E402


def parts(case, time):
    own = os.path.join(case, time, "lagrangian", "materialPoints")
    if os.path.isdir(own):
        return [case]
    procs = sorted(glob.glob(os.path.join(case, "processor*")),
                   key=lambda p: int(p.rsplit("processor", 1)[1]))
    return [p for p in procs
            if os.path.isdir(os.path.join(p, time, "lagrangian", "materialPoints"))]


def read_hdf5(path, fields):
    import h5py
    with h5py.File(path, "r") as h5:
        g = h5["materialPoints"]
        ids = g["pointId"][...].astype(np.int64)
        order = np.argsort(ids, kind="stable")
        out = {"positions": g["position"][...][order]}
        for f in fields:
            out[f] = g[f][...].reshape(len(ids), -1)[order]
    return ids[order], out


def read(case, time, fields):
    h5 = os.path.join(case, "HDF5", "materialPoints_%s.h5" % time)
    if not parts(case, time) and os.path.isfile(h5):
        return read_hdf5(h5, fields)
    data = {f: [] for f in fields}
    ids, pos = [], []
    for p in parts(case, time):
        ids.append(mpmPost.read_cloud_field(p, time, "pointId").astype(np.int64).reshape(-1))
        pos.append(mpmPost.read_positions(p, time))
        for f in fields:
            a = mpmPost.read_cloud_field(p, time, f)
            data[f].append(a.reshape(len(ids[-1]), -1))
    ids = np.concatenate(ids)
    order = np.argsort(ids, kind="stable")
    out = {"positions": np.concatenate(pos)[order]}
    for f in fields:
        out[f] = np.concatenate(data[f])[order]
    return ids[order], out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("time")
    ap.add_argument("--fields", nargs="*", default=["U", "stress", "mass", "F"])
    args = ap.parse_args()
    ida, A = read(args.a, args.time, args.fields)
    idb, B = read(args.b, args.time, args.fields)
    print("count", len(ida), len(idb))
    same = len(ida) == len(idb) and np.array_equal(ida, idb)
    print("ids equal", int(same))
    if not same:
        return 0
    for f in ["positions"] + args.fields:
        a, b = A[f], B[f]
        scale = np.ptp(a, axis=0).max() if f == "positions" else np.abs(a).max()
        diff = np.abs(a - b).max()
        print(f, diff/scale if scale > 0 else diff)
    return 0


if __name__ == "__main__":
    sys.exit(main())
