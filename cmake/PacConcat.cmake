# Concatenates ST files (SOURCES, a ;-list) into OUT, in order, for MATIEC's single-file iec2c.
file(WRITE "${OUT}" "")
foreach(src IN LISTS SOURCES)
  file(READ "${src}" text)
  file(APPEND "${OUT}" "(* ${src} *)\n${text}\n")
endforeach()
