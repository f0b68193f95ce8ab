#!/usr/bin/env bash
# ctest entry for tests/robustness/run.py: malformed scenes, bad options, output-path cases
# and bad machine files must all end in a clean, expected exit (table on stdout).
exec /usr/bin/python3 "$2/tests/robustness/run.py" "$1" --root "$2" --timeout 20
