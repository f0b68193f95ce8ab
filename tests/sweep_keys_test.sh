#!/usr/bin/env bash
# ctest entry for tests/sweep_keys_test.py: "did you mean" for a sweep file's keys and names.
NCUBE_SIMULATE="$1" exec /usr/bin/python3 "$2/tests/sweep_keys_test.py"
