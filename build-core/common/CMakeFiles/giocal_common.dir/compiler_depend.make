# Empty compiler generated dependencies file for giocal_common.
# This may be replaced when dependencies are built.
