#!/usr/bin/env bash
# ctest entry for tests/unknowns_test.py: the sampler of plausible worlds and the statistics of
# analysis/unknowns.md on canned worlds (issue 41).
exec /usr/bin/python3 "$2/tests/unknowns_test.py" "$2"
