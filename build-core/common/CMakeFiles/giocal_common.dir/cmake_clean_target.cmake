file(REMOVE_RECURSE
  "libgiocal_common.a"
)
