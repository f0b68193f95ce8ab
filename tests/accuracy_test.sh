#!/usr/bin/env bash
# ctest entry for tests/accuracy_test.py (the error measure against the reference).
exec /usr/bin/python3 "$2/tests/accuracy_test.py" "$1" "$2"
