#!/usr/bin/env bash
# ctest entry for tests/error_measure_test.py (the one error measure; B = E scores worst).
exec /usr/bin/python3 "$2/tests/error_measure_test.py" "$1" "$2"
