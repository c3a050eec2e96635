# pac_st_library(<target> SOURCES <file.st>... [GVL <list.st>...] [USER] [NATIVE <file.st>...]): translate
# Structured Text into a static C library; GVL names global constant lists to check with it
# (docs/constants.md). USER translates a user program (`pacst build --user`: PROGRAMs, global variable
# lists, located variables...; docs/translator.md, "User programs") and writes symbols.json beside
# POUS.h; NATIVE names ST files whose FUNCTIONs the C or C++ code linked with it implements (asserts).
# A USER library is translated by pacst with either compiler until the MATIEC backend writes the
# configuration a user program needs.
#
# With PAC_ST_COMPILER=pacst (default) the project's translator runs from a venv inside the build
# tree. It writes POUS.h (all types and POU interfaces) and one C file per ST file, and rewrites only
# the files whose text changed, so touching one .st file recompiles only that file's C unless its
# interface changed. With PAC_ST_COMPILER=matiec, iec2c compiles the ST files concatenated in the
# order given and one C translation unit includes the POUS.c it writes; C++ code sees pacst's POUS.h
# for the same files, and layout_check.c proves at compile time that both headers agree.
# List SOURCES in declaration order: a type before its users, a POU before its callers (`pacst order FILE...`
# prints it).

set(PACST_SOURCE_DIR "${CMAKE_CURRENT_LIST_DIR}/../translator" CACHE INTERNAL "")
# One venv for every preset's build tree (default, debug, ...), like the parse cache below: the packages
# are the same pinned versions, and installing them again per preset cost most of a configure. A build
# tree outside <source>/build keeps its own (PacSharedBuildDir.cmake).
include("${CMAKE_CURRENT_LIST_DIR}/PacSharedBuildDir.cmake")
pac_shared_build_dir(PAC_SHARED_BUILD_DIR "${CMAKE_CURRENT_LIST_DIR}/.." "${CMAKE_BINARY_DIR}")
set(PACST_VENV "${PAC_SHARED_BUILD_DIR}/venv" CACHE INTERNAL "")
set(PACST_PYTHON "${PACST_VENV}/bin/python" CACHE INTERNAL "")
# Parses are keyed by file content and blark's version, so every build tree (default, debug...) can
# share one cache and parse each version of a file once.
set(PACST_CACHE_DIR "${PAC_SHARED_BUILD_DIR}/pacst-cache" CACHE PATH "pacst's parse cache")
# #line directives: compiler messages, debuggers, sanitizers and gcov name the .st line of a statement.
option(PAC_ST_LINE_DIRECTIVES "pacst precedes each statement's C with #line naming its ST line" ON)
# One C unit per library (CMake's unity build of pacst's C files, as MATIEC's one POUS.c): the compiler then
# inlines the small FUNCTIONs into their callers, with EN and ENO folded away, and reads POUS.h once
# instead of once per ST file. Not for the library whose coverage is measured (pac_st_coverage: gcov's
# counters per file), nor where a change should recompile only its file (-DPAC_ST_UNITY=OFF);
# docs/benchmarks.md has what it saves.
option(PAC_ST_UNITY "Compile each translated ST library as one C unit" ON)

include("${CMAKE_CURRENT_LIST_DIR}/PacPythonVenv.cmake")
# pacst is needed with either compiler: with MATIEC it writes the declarations C++ code includes.
pac_python_venv("${PACST_VENV}" REQUIREMENTS "${PACST_SOURCE_DIR}/requirements.txt")
file(GLOB_RECURSE PACST_TOOL_FILES CONFIGURE_DEPENDS "${PACST_SOURCE_DIR}/pacst/*.py"
     "${PACST_SOURCE_DIR}/pacst/include/*.h")
# Its bytecode is kept in the build tree (never beside the sources), so that the build's and the tests' many runs
# of pacst load it instead of compiling every module again (PYTHONDONTWRITEBYTECODE would forbid it).
set(PACST_COMMAND env -u PYTHONDONTWRITEBYTECODE "PYTHONPYCACHEPREFIX=${CMAKE_BINARY_DIR}/pycache"
    "PYTHONPATH=${PACST_SOURCE_DIR}" "${PACST_PYTHON}" -m pacst CACHE INTERNAL "")
if(PAC_ST_COMPILER STREQUAL "matiec")
  if(NOT EXISTS "${IEC2C}" OR NOT EXISTS "${MATIEC_LIB}/C/iec_std_lib.h")
    message(FATAL_ERROR "PAC_ST_COMPILER=matiec needs -DIEC2C=<path to iec2c> and "
                        "-DMATIEC_LIB=<MATIEC's lib folder, holding C/iec_std_lib.h>")
  endif()
elseif(NOT PAC_ST_COMPILER STREQUAL "pacst")
  message(FATAL_ERROR "PAC_ST_COMPILER must be pacst or matiec, not '${PAC_ST_COMPILER}'")
endif()

function(pac_st_library target)
  cmake_parse_arguments(ARG "USER" "" "SOURCES;GVL;NATIVE" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "pac_st_library(${target}): no SOURCES")
  endif()
  set(out "${CMAKE_CURRENT_BINARY_DIR}/${target}.st-c")
  set(abs_sources "")
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(abs "${src}" ABSOLUTE)
    list(APPEND abs_sources "${abs}")
  endforeach()
  # Global constant lists: checked with the POUs (whose constants must repeat them unchanged) and
  # written as <stem>.h, a name/value table for C and C++ code.
  set(gvl_args "")
  set(gvl_sources "")
  set(gvl_headers "")
  foreach(gvl IN LISTS ARG_GVL)
    get_filename_component(abs "${gvl}" ABSOLUTE)
    get_filename_component(stem "${gvl}" NAME_WE)
    list(APPEND gvl_args --gvl "${abs}")
    list(APPEND gvl_sources "${abs}")
    list(APPEND gvl_headers "${stem}.h")
  endforeach()
  list(TRANSFORM gvl_headers PREPEND "${out}/" OUTPUT_VARIABLE out_gvl_headers)
  list(TRANSFORM gvl_headers PREPEND "${out}/decl/" OUTPUT_VARIABLE decl_gvl_headers)

  set(user_args "")
  set(user_outputs "")
  if(ARG_USER)
    list(APPEND user_args --user)
    list(APPEND user_outputs "${out}/symbols.json")
    foreach(native IN LISTS ARG_NATIVE)
      get_filename_component(abs "${native}" ABSOLUTE)
      list(APPEND user_args --native "${abs}")
      list(APPEND gvl_sources "${abs}")  # a dependency of the translation like the lists
    endforeach()
  elseif(ARG_NATIVE)
    message(FATAL_ERROR "pac_st_library(${target}): NATIVE needs USER")
  endif()

  if(PAC_ST_COMPILER STREQUAL "pacst" OR ARG_USER)
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
    set(line_args "")
    if(PAC_ST_LINE_DIRECTIVES)
      set(line_args --line-directives)
    endif()
    add_custom_command(
      OUTPUT "${out}/pacst.stamp"
      BYPRODUCTS "${out}/POUS.h" "${out}/pacst_iec.h" "${out}/pacst_enum_names.h" ${c_files} ${out_gvl_headers}
                 ${user_outputs}
      COMMAND ${PACST_COMMAND} build --out "${out}" --cache "${PACST_CACHE_DIR}"
              --stamp "${out}/pacst.stamp" ${line_args} ${gvl_args} ${user_args} ${abs_sources}
      DEPENDS ${abs_sources} ${gvl_sources} ${PACST_TOOL_FILES}
      COMMENT "pacst: translating ${target} (${CMAKE_CURRENT_SOURCE_DIR})"
      VERBATIM)
    add_custom_target(${target}_translate DEPENDS "${out}/pacst.stamp")
    add_library(${target} STATIC ${c_files})
    add_dependencies(${target} ${target}_translate)
    if(PAC_ST_UNITY)
      set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 0)
    endif()
    target_include_directories(${target} PUBLIC "${out}")
  else()
    # MATIEC's object code, pacst's declarations for C++ (MATIEC's POUS.h is not valid C++), and a
    # compile-time check that both lay out every type and FB alike (docs/translator.md).
    set(decl "${out}/decl")  # where decl_gvl_headers are
    set(mat "${out}/matiec")
    set(all_st "${mat}/all.st")
    add_custom_command(
      OUTPUT "${mat}/POUS.c" "${mat}/POUS.h"
      COMMAND ${CMAKE_COMMAND} -E make_directory "${mat}"
      COMMAND ${CMAKE_COMMAND} "-DOUT=${all_st}" "-DSOURCES=${abs_sources}"
              -P "${PROJECT_SOURCE_DIR}/cmake/PacConcat.cmake"
      COMMAND "${IEC2C}" -I "${MATIEC_LIB}" -T "${mat}" "${all_st}"
      DEPENDS ${abs_sources}
      COMMENT "iec2c: compiling ${target}"
      VERBATIM)
    add_custom_command(
      OUTPUT "${decl}/pacst.stamp"
      BYPRODUCTS "${decl}/POUS.h" "${decl}/pacst_iec.h" "${decl}/pacst_enum_names.h" "${decl}/layout_probe.c" "${mat}/layout_check.c"
                 ${decl_gvl_headers}
      COMMAND ${PACST_COMMAND} declare --out "${decl}" --check-out "${mat}" --cache "${PACST_CACHE_DIR}"
              --stamp "${decl}/pacst.stamp" ${gvl_args} ${abs_sources}
      DEPENDS ${abs_sources} ${gvl_sources} ${PACST_TOOL_FILES}
      COMMENT "pacst: declarations of ${target} for C++"
      VERBATIM)
    add_custom_target(${target}_declare DEPENDS "${decl}/pacst.stamp")
    add_executable(${target}_layout_probe "${decl}/layout_probe.c")
    add_dependencies(${target}_layout_probe ${target}_declare)
    target_include_directories(${target}_layout_probe PRIVATE "${decl}")
    # It asks of every integer type whether -1 is below 0, which for the unsigned ones is the point.
    target_compile_options(${target}_layout_probe PRIVATE -Wno-type-limits)
    add_custom_command(
      OUTPUT "${mat}/layout_expected.h"
      COMMAND ${target}_layout_probe "${mat}/layout_expected.h"
      DEPENDS ${target}_layout_probe
      COMMENT "pacst: measuring the layout of ${target}'s declarations"
      VERBATIM)
    file(MAKE_DIRECTORY "${mat}")
    # MATIEC's POUS.c includes nothing itself: its library and declarations come first.
    file(WRITE "${mat}/unit.c.in" "#include \"iec_std_lib.h\"\n#include \"POUS.h\"\n#include \"POUS.c\"\n")
    configure_file("${mat}/unit.c.in" "${mat}/unit.c" COPYONLY)
    add_library(${target} STATIC "${mat}/unit.c" "${mat}/layout_check.c")
    add_dependencies(${target} ${target}_declare)
    set_source_files_properties("${mat}/unit.c" PROPERTIES OBJECT_DEPENDS "${mat}/POUS.c;${mat}/POUS.h")
    set_source_files_properties("${mat}/layout_check.c" PROPERTIES GENERATED TRUE
                                OBJECT_DEPENDS "${mat}/layout_expected.h;${mat}/POUS.h")
    target_include_directories(${target} PRIVATE "${mat}" "${MATIEC_LIB}/C" INTERFACE "${decl}")
    # MATIEC's STRING (126 characters) in every file that sees these declarations, whichever copy of
    # pacst_iec.h it includes first (the declarations' or the translator's)
    target_compile_definitions(${target} INTERFACE PACST_MATIEC_STRING=1)
  endif()
  # IEC integer overflow wraps; C only promises that with -fwrapv.
  target_compile_options(${target} PRIVATE -fwrapv -Wno-unused-function -Wno-unused-variable
                         -Wno-unused-parameter -Wno-unused-label -Wno-type-limits)
  target_link_libraries(${target} PUBLIC m)
endfunction()
