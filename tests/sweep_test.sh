#!/usr/bin/env bash
# ctest entry for tests/sweep_test.py: sweep files through the real Snakemake.
NCUBE_SIMULATE="$1" exec /usr/bin/python3 "$2/tests/sweep_test.py"
