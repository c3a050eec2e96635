# Line and branch coverage of the library's ST (docs/testing.md#st-coverage).
#
# With PAC_COVERAGE, pac_st_coverage(<ST library target>) compiles that library's generated C with gcov
# instrumentation and without optimisation; pacst's #line directives make gcov count every statement
# on its .st line. Two targets then report on the .st files, per POU, through gcovr (pinned, in a venv
# of the build tree):
#   coverage_report  from the counters the tests left (after ctest); fails when a target is missed
#   coverage         resets the counters, runs the whole suite, then reports
#   coverage_reset   deletes the counters
# Both print the table and write build/.../coverage/index.html (annotated ST) and summary.json.
include_guard(GLOBAL)

option(PAC_COVERAGE "Measure line and branch coverage of the library's ST (the coverage targets)" OFF)

if(PAC_COVERAGE)
  include("${CMAKE_CURRENT_LIST_DIR}/PacPythonVenv.cmake")
  set(PAC_COVERAGE_VENV "${CMAKE_BINARY_DIR}/coverage-venv")
  pac_python_venv("${PAC_COVERAGE_VENV}" REQUIREMENTS "${CMAKE_CURRENT_LIST_DIR}/coverage-requirements.txt")
endif()

function(pac_st_coverage target)
  if(NOT PAC_COVERAGE)
    return()
  endif()
  if(NOT PAC_ST_COMPILER STREQUAL "pacst")
    message(FATAL_ERROR "PAC_COVERAGE needs PAC_ST_COMPILER=pacst: only pacst writes the #line directives")
  endif()
  # -O0 after the build type's flags: optimised code merges and moves lines. One C file per ST file
  # (no unity build for this library): st_coverage.py reads the counters per object file.
  target_compile_options(${target} PRIVATE --coverage -O0)
  set_target_properties(${target} PROPERTIES UNITY_BUILD OFF)
  target_link_options(${target} INTERFACE --coverage)

  set(out "${CMAKE_BINARY_DIR}/coverage")
  set(report "${PAC_COVERAGE_VENV}/bin/python" "${PROJECT_SOURCE_DIR}/cmake/st_coverage.py"
             --gcovr "${PAC_COVERAGE_VENV}/bin/gcovr" --root "${PROJECT_SOURCE_DIR}"
             --objects "$<TARGET_FILE_DIR:${target}>" --out "${out}"
             --exceptions "${PROJECT_SOURCE_DIR}/tests/coverage_exceptions.txt")
  add_custom_target(coverage_reset COMMAND ${report} --reset VERBATIM)
  add_custom_target(coverage_report
    COMMAND ${report}
    WORKING_DIRECTORY "${CMAKE_BINARY_DIR}"
    COMMENT "ST coverage of ${target} from the counters of the last test run"
    VERBATIM USES_TERMINAL)
  add_custom_target(coverage
    COMMAND ${report} --reset
    COMMAND "${CMAKE_CTEST_COMMAND}" --output-on-failure -j 2
    COMMAND ${report}
    WORKING_DIRECTORY "${CMAKE_BINARY_DIR}"
    COMMENT "ST coverage: the whole suite, then the report"
    VERBATIM USES_TERMINAL)
endfunction()
