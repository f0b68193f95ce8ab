#!/usr/bin/env bash
# ctest entry for tests/robustness/run.py's cases of the files a run reads (tests/robustness/
# cases.py, PARTS["files"]): malformed scenes, SimGrid settings, bad machine and model files
# must all end in a clean, expected exit (tables on stdout), two runs at a time. The cases of
# the command line are tests/robustness_test.sh.
exec /usr/bin/python3 "$2/tests/robustness/run.py" "$1" --root "$2" --timeout 20 --strict \
  --only files --jobs 2
