# Empty compiler generated dependencies file for giocal_ekf.
# This may be replaced when dependencies are built.
