#!/usr/bin/env bash
# ctest entry for the cells of tests/robustness/threat_model.py that write a file: every output
# of ./simulate and the other tools x every kind of path and every input of the run, each clean
# unless listed in tests/robustness/known_open.py (--strict fails on a listed one that now is;
# tables on stdout). The cells that read are tests/robustness_reads_test.sh, the cases of
# tests/robustness/cases.py tests/robustness_test.sh and tests/robustness_files_test.sh.
exec /usr/bin/python3 "$2/tests/robustness/run.py" "$1" --root "$2" --timeout 20 --strict \
  --only writes --jobs 2
