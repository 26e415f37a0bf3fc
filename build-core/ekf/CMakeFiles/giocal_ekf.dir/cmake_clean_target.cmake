file(REMOVE_RECURSE
  "libgiocal_ekf.a"
)
