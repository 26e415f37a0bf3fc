file(REMOVE_RECURSE
  "libgiocal_evaluation.a"
)
