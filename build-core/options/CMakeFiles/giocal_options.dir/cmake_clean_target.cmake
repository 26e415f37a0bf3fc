file(REMOVE_RECURSE
  "libgiocal_options.a"
)
