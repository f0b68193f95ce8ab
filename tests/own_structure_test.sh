#!/bin/bash
# ctest entry for tests/own_structure_test.py (each method against its own structure: the
# paired ratio of two truths, the front, the decisions at equal cost and their sentences).
exec /usr/bin/python3 "$2/tests/own_structure_test.py" "$2"
