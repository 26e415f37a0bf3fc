# Empty compiler generated dependencies file for giocal_sim.
# This may be replaced when dependencies are built.
