#!/usr/bin/env bash
# Every program and script the repository ships is tried by a test (tests/robustness/
# executables.py: a new one fails here until it is listed with the tests that try it, or as
# open with why, and until docs/threat-model.md's table, written from that list, names it); and
# every Python one is tried from its own argparse options (tests/robustness/options_harness.py:
# each path option given a FIFO, /dev/zero, a folder, a link to a committed file, a committed
# file and a missing folder; each number 0, -1, nan, 1e400 and 0x10; each JSON input nested
# deeply, with a NaN, negated, of the wrong types), in a copy of the tracked tree, each case
# ending in a documented exit with one line and no traceback, within its time and memory, the
# copy's git status unchanged. About 300 cases, each a fork of one process that imported
# numpy and matplotlib once.
root="$2"
failed=0
/usr/bin/python3 "$root/tests/robustness/executables.py" "$root" || failed=1
/usr/bin/python3 "$root/tests/robustness/options_harness.py" "$root" "$1" --jobs 2 || failed=1
exit "$failed"
