# The CTest fixture of the refusal snippets: one `pacst check --separately` run over every DIR/*.st
# (PACST: the translator command, a ;-list; DIR: the snippets; CACHE: pacst's parse cache), its messages
# written to REPORT for test_refuse.cpp. Exit code 1 is pacst refusing snippets, which is the point; only
# a translator that could not run fails the fixture.
file(GLOB snippets "${DIR}/*.st")
list(SORT snippets)
# MODE: extra options of the check (`--user` for the user-program refusals, with their --native files).
execute_process(COMMAND ${PACST} check --separately ${MODE} --cache "${CACHE}" ${snippets}
                OUTPUT_FILE "${REPORT}" ERROR_FILE "${REPORT}" RESULT_VARIABLE rc)
if(NOT rc MATCHES "^[01]$")
  message(FATAL_ERROR "pacst did not run on the refusal snippets (${rc}); see ${REPORT}")
endif()
