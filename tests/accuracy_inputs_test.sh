#!/usr/bin/env bash
# ctest entry for tests/accuracy_inputs_test.py (accuracy.py's refusals).
exec /usr/bin/python3 "$2/tests/accuracy_inputs_test.py" "$1" "$2"
