file(REMOVE_RECURSE
  "libgiocal_import.a"
)
