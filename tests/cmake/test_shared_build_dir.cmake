# Build.SharedFolder: the venvs and the parse cache go where pac_shared_build_dir says: shared under
# <source>/build by the presets' trees, inside the build tree itself for any other, so an out-of-tree
# `cmake -B /elsewhere` writes nothing into the source tree. Run with cmake -P.
include("${CMAKE_CURRENT_LIST_DIR}/../../cmake/PacSharedBuildDir.cmake")

function(expect source binary wanted)
  pac_shared_build_dir(got "${source}" "${binary}")
  if(NOT got STREQUAL wanted)
    message(FATAL_ERROR "pac_shared_build_dir(${source}, ${binary}) is ${got}, expected ${wanted}")
  endif()
endfunction()

expect(/src/pac /src/pac/build /src/pac/build)              # the default preset
expect(/src/pac /src/pac/build/debug /src/pac/build)        # the other presets share it
expect(/src/pac /elsewhere/pac-build /elsewhere/pac-build)  # out of tree: its own
expect(/src/pac /src/pac/build-gcc13 /src/pac/build-gcc13)  # a name that only starts like build/
expect(/src/pac/ /src/pac/./build/fuzz /src/pac/build)      # spelled otherwise
expect(/src/a+b /src/a+b/build/debug /src/a+b/build)        # a path with a regex's characters
expect(/src/pac /src/pacXbuild /src/pacXbuild)
message(STATUS "the shared build folder: the presets' trees share <source>/build, any other keeps its own")
