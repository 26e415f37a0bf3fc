# Empty dependencies file for giocal_import.
# This may be replaced when dependencies are built.
