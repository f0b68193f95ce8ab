# Empty dependencies file for simulate.
# This may be replaced when dependencies are built.
