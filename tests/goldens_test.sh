#!/usr/bin/env bash
# ctest entry for tests/goldens/goldens.py: whole runs pinned to their simulated seconds and
# iteration counts (regenerate on purpose: tests/goldens/regenerate).
exec /usr/bin/python3 "$2/tests/goldens/goldens.py" check "$1"
