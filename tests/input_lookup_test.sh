#!/usr/bin/env bash
# ctest entry for tests/input_lookup_test.py: ./simulate and the sweep tool find the scene,
# the platform and the cost model by one rule, from any folder.
NCUBE_SIMULATE="$1" exec /usr/bin/python3 "$2/tests/input_lookup_test.py"
