#!/usr/bin/env bash
# ctest entry for the cells of tests/robustness/threat_model.py that read a file: every input of
# ./simulate and the other tools x every kind of path and hostile content that applies, each
# clean unless listed in tests/robustness/known_open.py (--strict fails on a listed one that now
# is; tables on stdout). The cells that write are tests/robustness_writes_test.sh, the cases of
# tests/robustness/cases.py tests/robustness_test.sh and tests/robustness_files_test.sh: ctest
# entries of about a minute each, two runs at a time.
exec /usr/bin/python3 "$2/tests/robustness/run.py" "$1" --root "$2" --timeout 20 --strict \
  --only reads --jobs 2
