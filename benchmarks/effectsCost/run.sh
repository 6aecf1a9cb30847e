#!/bin/bash
# What each effect costs: one coupled scene run with the effects added one at
# a time, and the core's step with and without its fluid-coupling hooks.
# See README.md and run.py (options: --steps --rounds --keep).
cd "${0%/*}" || exit 1
if [ -z "${MPMFOAM_DIR:-}" ] || ! command -v mpmFoam >/dev/null 2>&1; then
    . ../../etc/bashrc
fi
exec "${MPMFOAM_PYTHON:-python3}" run.py "$@"
