#!/bin/bash
# Write and restart-read time and size on disk of the material points in
# OpenFOAM ASCII, OpenFOAM binary and HDF5, serial and on 2 ranks (run.py).
#   ./run.sh [cells per side ...]     (default 50: 50^3 cells x 8 = 1 M points)
cd "${0%/*}" || exit 1
if [ -z "${MPMFOAM_DIR:-}" ] || ! command -v mpmFoam >/dev/null 2>&1; then
    . ../../etc/bashrc
fi
exec "${MPMFOAM_PYTHON:-python3}" run.py "$@"
