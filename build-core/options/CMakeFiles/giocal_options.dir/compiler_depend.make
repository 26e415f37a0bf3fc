# Empty compiler generated dependencies file for giocal_options.
# This may be replaced when dependencies are built.
