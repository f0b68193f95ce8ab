# Empty dependencies file for ncube.
# This may be replaced when dependencies are built.
