#!/usr/bin/env bash
# ctest entry for tests/sweep_scene_files_test.py: a sweep keeps files of one scene name apart.
NCUBE_SIMULATE="$1" exec /usr/bin/python3 "$2/tests/sweep_scene_files_test.py"
