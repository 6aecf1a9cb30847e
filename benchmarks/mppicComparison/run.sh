#!/bin/bash
# mpmFoam vs MPPICFoam (--scene bed, the default) or MPPICInterFoam (--scene
# vof), cost per fluid step on the same scene.
# Builds both cases in a mktemp folder and runs them in turn; see README.md
# and run.py (options: --scene --steps --deltaT --rounds --warmup --timeout --keep).
cd "${0%/*}" || exit 1
if [ -z "${MPMFOAM_DIR:-}" ] || ! command -v mpmFoam >/dev/null 2>&1; then
    . ../../etc/bashrc
fi
for s in MPPICFoam MPPICInterFoam; do
    command -v $s >/dev/null || { echo "$s not found" >&2; exit 1; }
done
exec "${MPMFOAM_PYTHON:-python3}" run.py "$@"
