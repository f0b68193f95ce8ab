#!/usr/bin/env bash
# ctest entry for tests/robustness/run.py's threat model (tests/robustness/threat_model.py):
# every cell (every input and output of ./simulate and the other tools x every kind of path and
# hostile content) not listed in tests/robustness/known_open.py must be clean, and --strict
# fails on a listed one that now is (tables on stdout). The cases of tests/robustness/cases.py
# are tests/robustness_test.sh.
exec /usr/bin/python3 "$2/tests/robustness/run.py" "$1" --root "$2" --timeout 20 --strict \
  --only threats --jobs 2
