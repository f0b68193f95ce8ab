#!/usr/bin/env bash
# ctest entry for tests/sweep_shell_words_test.py: shell syntax, spaces, quotes, braces, percent
# signs and newlines in every string a user controls (sweep name, sweep-file and scene paths,
# results path, cfg values, the Slurm submit line) run nothing and either work or are refused
# with one line (issue 37, item 1).
# Usage: bash tests/sweep_shell_words_test.sh <path-to-simulate-binary> <repo-root>
# CI=true: Snakemake 7's cluster executors sleep 10 s between rounds of status checks,
# 1 s with CI=true (snakemake/executors/__init__.py, sleep()); nothing else reads it.
CI=true NCUBE_SIMULATE="$1" exec /usr/bin/python3 "$2/tests/sweep_shell_words_test.py"
