#!/bin/bash
# ctest entry for tests/openings_test.py (every results page opens with what its tables say; the
# paper's headline recomputed on the committed numbers).
exec /usr/bin/python3 "$2/tests/openings_test.py" "$2"
