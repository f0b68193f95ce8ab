#!/usr/bin/env bash
# ctest entry for tests/sweep_test.py: sweep files through the real Snakemake.
# CI=true: Snakemake 7's cluster executors sleep 10 s between rounds of status checks,
# 1 s with CI=true (snakemake/executors/__init__.py, sleep()); nothing else reads it.
CI=true NCUBE_SIMULATE="$1" exec /usr/bin/python3 "$2/tests/sweep_test.py"
