# Empty compiler generated dependencies file for giocal.
# This may be replaced when dependencies are built.
