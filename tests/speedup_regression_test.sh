#!/usr/bin/env bash
# ctest entry for tests/speedup_regression.py: speedup-curve shapes against the record.
exec /usr/bin/python3 "$2/tests/speedup_regression.py" "$1"
