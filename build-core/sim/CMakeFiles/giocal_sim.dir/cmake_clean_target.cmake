file(REMOVE_RECURSE
  "libgiocal_sim.a"
)
