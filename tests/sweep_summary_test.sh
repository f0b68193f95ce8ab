#!/usr/bin/env bash
# ctest entry for tests/sweep_summary_test.py: a sweep's printed answer, summary and plots.
NCUBE_SIMULATE="$1" exec /usr/bin/python3 "$2/tests/sweep_summary_test.py"
