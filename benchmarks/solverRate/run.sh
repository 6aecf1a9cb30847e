#!/bin/bash
# The solver's own one-thread rate on a pure-MPM 3D block (see run.py).
cd "${0%/*}" || exit 1
if [ -z "${MPMFOAM_DIR:-}" ] || ! command -v mpmFoam >/dev/null 2>&1; then
    . ../../etc/bashrc
fi
exec "${MPMFOAM_PYTHON:-python3}" run.py "$@"
