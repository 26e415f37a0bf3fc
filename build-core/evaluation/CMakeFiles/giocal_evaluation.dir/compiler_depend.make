# Empty compiler generated dependencies file for giocal_evaluation.
# This may be replaced when dependencies are built.
