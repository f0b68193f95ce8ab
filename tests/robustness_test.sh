#!/usr/bin/env bash
# ctest entry for tests/robustness/run.py's cases of the command line (tests/robustness/
# cases.py, PARTS["options"]): bad option sets, every numeric option's special values and range
# ends, output-path cases must all end in a clean, expected exit (tables on stdout), two runs at
# a time. The cases of the files a run reads are tests/robustness_files_test.sh, the threat
# model's cells tests/robustness_reads_test.sh and tests/robustness_writes_test.sh.
exec /usr/bin/python3 "$2/tests/robustness/run.py" "$1" --root "$2" --timeout 20 --strict \
  --only options --jobs 2
