# Empty compiler generated dependencies file for giocal_replay.
# This may be replaced when dependencies are built.
