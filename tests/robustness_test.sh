#!/usr/bin/env bash
# ctest entry for tests/robustness/run.py: malformed scenes, bad options, output-path cases
# and bad machine files must all end in a clean, expected exit, and so must every cell of the
# threat model (tests/robustness/threat_model.py) not listed in tests/robustness/known_open.py
# (tables on stdout).
exec /usr/bin/python3 "$2/tests/robustness/run.py" "$1" --root "$2" --timeout 20 --strict
