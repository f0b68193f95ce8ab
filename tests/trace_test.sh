#!/usr/bin/env bash
# ctest entry for tests/trace_test.py: the trace's events carry their arguments, its windows
# keep what they say, and the message log names the kinds.
NCUBE_SIMULATE="$1" exec /usr/bin/python3 "$2/tests/trace_test.py"
