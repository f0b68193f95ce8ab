#!/usr/bin/env bash
# ctest entry for tests/docs_figures.py: the figures the docs quote against the code and the
# short runs that give them.
exec /usr/bin/python3 "$2/tests/docs_figures.py" "$1"
