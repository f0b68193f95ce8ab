#!/usr/bin/env bash
# ctest entry for tests/robustness/run.py's cases (tests/robustness/cases.py): malformed scenes,
# bad options, every numeric option's special values and range ends, output-path cases,
# SimGrid settings, bad machine and model files must all end in a clean, expected exit (tables
# on stdout), two runs at a time. The threat model's cells are tests/robustness_reads_test.sh
# and tests/robustness_writes_test.sh.
exec /usr/bin/python3 "$2/tests/robustness/run.py" "$1" --root "$2" --timeout 20 --strict \
  --only cases --jobs 2
