file(REMOVE_RECURSE
  "libgiocal_replay.a"
)
