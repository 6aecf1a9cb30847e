#!/bin/bash
# Strong scaling of decomposed mpmFoam runs (see run.py and README.md).
cd "${0%/*}" || exit 1
if [ -z "${MPMFOAM_DIR:-}" ] || ! command -v mpmFoam >/dev/null 2>&1; then
    . ../../etc/bashrc
fi
exec "${MPMFOAM_PYTHON:-python3}" run.py "$@"
