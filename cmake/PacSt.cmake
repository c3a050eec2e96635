# pac_st_library(<target> SOURCES <file.st>...): translate Structured Text into a static C library.
#
# With PAC_ST_COMPILER=pacst (default) the project's translator runs from a venv inside the build
# tree. It writes POUS.h (all types and POU interfaces) and one C file per ST file, and rewrites only
# the files whose text changed, so touching one .st file recompiles only that file's C unless its
# interface changed. With PAC_ST_COMPILER=matiec, iec2c compiles the ST files concatenated in the
# order given, and one C translation unit includes the POUS.c it writes.
# List SOURCES in declaration order: a type before its users, a POU before its callers.

set(PACST_SOURCE_DIR "${CMAKE_CURRENT_LIST_DIR}/../translator" CACHE INTERNAL "")
set(PACST_VENV "${CMAKE_BINARY_DIR}/venv" CACHE INTERNAL "")
set(PACST_PYTHON "${PACST_VENV}/bin/python" CACHE INTERNAL "")
# Parses are keyed by file content and blark's version, so every build tree (default, debug...) can
# share one cache and parse each version of a file once.
set(PACST_CACHE_DIR "${CMAKE_CURRENT_LIST_DIR}/../build/pacst-cache" CACHE PATH "pacst's parse cache")

function(_pacst_ensure_venv)
  set(req "${PACST_SOURCE_DIR}/requirements.txt")
  file(SHA256 "${req}" req_hash)
  set(stamp "${PACST_VENV}/.requirements-${req_hash}")
  if(EXISTS "${stamp}")
    return()
  endif()
  find_package(Python3 3.9 REQUIRED COMPONENTS Interpreter)
  message(STATUS "pacst: creating ${PACST_VENV} with ${req}")
  execute_process(COMMAND "${Python3_EXECUTABLE}" -m venv "${PACST_VENV}" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "pacst: could not create a venv (on Debian: apt-get install python3-venv)")
  endif()
  execute_process(COMMAND "${PACST_PYTHON}" -m pip install --quiet --disable-pip-version-check
                          -r "${req}" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "pacst: pip could not install ${req}")
  endif()
  file(GLOB old "${PACST_VENV}/.requirements-*")
  if(old)
    file(REMOVE ${old})
  endif()
  file(TOUCH "${stamp}")
endfunction()

if(PAC_ST_COMPILER STREQUAL "pacst")
  _pacst_ensure_venv()
  file(GLOB_RECURSE PACST_TOOL_FILES CONFIGURE_DEPENDS "${PACST_SOURCE_DIR}/pacst/*.py"
       "${PACST_SOURCE_DIR}/pacst/include/*.h")
  # The translator as a command, for tests that run it on snippets.
  set(PACST_COMMAND env "PYTHONPATH=${PACST_SOURCE_DIR}" "${PACST_PYTHON}" -m pacst CACHE INTERNAL "")
elseif(PAC_ST_COMPILER STREQUAL "matiec")
  if(NOT EXISTS "${IEC2C}" OR NOT EXISTS "${MATIEC_LIB}/C/iec_std_lib.h")
    message(FATAL_ERROR "PAC_ST_COMPILER=matiec needs -DIEC2C=<path to iec2c> and "
                        "-DMATIEC_LIB=<MATIEC's lib folder, holding C/iec_std_lib.h>")
  endif()
else()
  message(FATAL_ERROR "PAC_ST_COMPILER must be pacst or matiec, not '${PAC_ST_COMPILER}'")
endif()

function(pac_st_library target)
  cmake_parse_arguments(ARG "" "" "SOURCES" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "pac_st_library(${target}): no SOURCES")
  endif()
  set(out "${CMAKE_CURRENT_BINARY_DIR}/${target}.st-c")
  set(abs_sources "")
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(abs "${src}" ABSOLUTE)
    list(APPEND abs_sources "${abs}")
  endforeach()

  if(PAC_ST_COMPILER STREQUAL "pacst")
    set(c_files "")
    set(stems "")
    foreach(abs IN LISTS abs_sources)
      get_filename_component(stem "${abs}" NAME_WE)
      if(stem IN_LIST stems)
        message(FATAL_ERROR "pac_st_library(${target}): two ST files named ${stem}")
      endif()
      list(APPEND stems "${stem}")
      list(APPEND c_files "${out}/${stem}.c")
    endforeach()
    # The stamp is the one real output; the C files are byproducts that keep their time stamp when
    # their text did not change, so Ninja and Make recompile only what really changed.
    add_custom_command(
      OUTPUT "${out}/pacst.stamp"
      BYPRODUCTS "${out}/POUS.h" "${out}/pacst_iec.h" ${c_files}
      COMMAND ${PACST_COMMAND} build --out "${out}" --cache "${PACST_CACHE_DIR}"
              --stamp "${out}/pacst.stamp" ${abs_sources}
      DEPENDS ${abs_sources} ${PACST_TOOL_FILES}
      COMMENT "pacst: translating ${target} (${CMAKE_CURRENT_SOURCE_DIR})"
      VERBATIM)
    add_custom_target(${target}_translate DEPENDS "${out}/pacst.stamp")
    add_library(${target} STATIC ${c_files})
    add_dependencies(${target} ${target}_translate)
    target_include_directories(${target} PUBLIC "${out}")
  else()
    set(all_st "${out}/all.st")
    add_custom_command(
      OUTPUT "${out}/POUS.c" "${out}/POUS.h"
      COMMAND ${CMAKE_COMMAND} -E make_directory "${out}"
      COMMAND ${CMAKE_COMMAND} "-DOUT=${all_st}" "-DSOURCES=${abs_sources}"
              -P "${PROJECT_SOURCE_DIR}/cmake/PacConcat.cmake"
      COMMAND "${IEC2C}" -I "${MATIEC_LIB}" -T "${out}" "${all_st}"
      DEPENDS ${abs_sources}
      COMMENT "iec2c: compiling ${target}"
      VERBATIM)
    file(MAKE_DIRECTORY "${out}")
    file(WRITE "${out}/unit.c.in" "#include \"POUS.c\"\n")
    configure_file("${out}/unit.c.in" "${out}/unit.c" COPYONLY)
    add_library(${target} STATIC "${out}/unit.c")
    set_source_files_properties("${out}/unit.c" PROPERTIES OBJECT_DEPENDS "${out}/POUS.c")
    target_include_directories(${target} PUBLIC "${out}" "${MATIEC_LIB}/C")
  endif()
  # IEC integer overflow wraps; C only promises that with -fwrapv.
  target_compile_options(${target} PRIVATE -fwrapv -Wno-unused-function -Wno-unused-variable
                         -Wno-unused-parameter -Wno-unused-label -Wno-type-limits)
  target_link_libraries(${target} PUBLIC m)
endfunction()
