#!/usr/bin/env bash
# ctest entry for tests/sweep_failures_test.py: how a local sweep ends when something fails.
NCUBE_SIMULATE="$1" exec /usr/bin/python3 "$2/tests/sweep_failures_test.py"
