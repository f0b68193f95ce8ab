#!/usr/bin/env bash
# ctest entry for tests/sweep_input_file_test.py (the sweep tool's input gate, path kind by kind).
exec /usr/bin/python3 "$2/tests/sweep_input_file_test.py"
