#!/usr/bin/env bash
# ctest entry for tests/platform_nodes_cache_test.py: the sweep library's cache of platforms'
# node counts (analysis/ncube/sweep.py, build/platform-nodes) asks ./simulate once per platform
# and build, and again when the platform or the simulator changes.
exec /usr/bin/python3 "$2/tests/platform_nodes_cache_test.py" "$1"
