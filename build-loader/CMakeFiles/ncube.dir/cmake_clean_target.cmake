file(REMOVE_RECURSE
  "libncube.a"
)
