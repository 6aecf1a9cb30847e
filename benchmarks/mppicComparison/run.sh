#!/bin/bash
# mpmFoam vs MPPICFoam, cost per fluid step on one fluidised-bed scene.
# Builds both cases in a mktemp folder and runs them in turn; see README.md
# and run.py (options: --steps --deltaT --rounds --warmup --keep).
cd "${0%/*}" || exit 1
if [ -z "${MPMFOAM_DIR:-}" ] || ! command -v mpmFoam >/dev/null 2>&1; then
    . ../../etc/bashrc
fi
command -v MPPICFoam >/dev/null || { echo "MPPICFoam not found" >&2; exit 1; }
exec "${MPMFOAM_PYTHON:-python3}" run.py "$@"
