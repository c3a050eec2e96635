# pac_shared_build_dir(<var> <source dir> <binary dir>): the folder for what every build tree of one checkout
# may share (the translator's venv, pacst's parse cache, the pyserial venv): <source>/build for the
# presets' trees (build/, build/debug, ...), so a second preset installs nothing again, and the build
# tree itself for any other (`cmake -B /elsewhere` writes nothing into the source tree).
include_guard(GLOBAL)

function(pac_shared_build_dir var source binary)
  get_filename_component(presets "${source}/build" ABSOLUTE)
  get_filename_component(tree "${binary}" ABSOLUTE)
  string(LENGTH "${presets}/" length)
  string(SUBSTRING "${tree}/" 0 ${length} head)  # a prefix, not a regex: a path may hold '+' or '.'
  if(head STREQUAL "${presets}/")
    set(${var} "${presets}" PARENT_SCOPE)
  else()
    set(${var} "${tree}" PARENT_SCOPE)
  endif()
endfunction()
