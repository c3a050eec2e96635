# UserPrograms.Matiec: the user-program plant of user/ (all but the native asserts and the program that
# calls them) through `pacst matiec` (one ST file with the CONFIGURATION, RESOURCE and TASKs) into MATIEC's
# iec2c, and its C compiled against MATIEC's library. PACST: the translator command (a ;-list); IEC2C,
# MATIEC_LIB: MATIEC (IEC2C empty: only `pacst matiec`, UserPrograms.PacstMatiec in the pacst build, so a
# construct wrongly taken for dialect shows without MATIEC); SOURCES: the ST files; TASKS: the task list;
# OUT: a scratch folder; CC: a C compiler.
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}/c")
execute_process(COMMAND ${PACST} matiec --out "${OUT}/user.st" --tasks "${TASKS}" ${SOURCES}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pacst matiec failed (${rc})")
endif()
if("${IEC2C}" STREQUAL "")
  return()
endif()
execute_process(COMMAND "${IEC2C}" -I "${MATIEC_LIB}" -T "${OUT}/c" "${OUT}/user.st" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "iec2c refused ${OUT}/user.st (${rc})")
endif()
execute_process(COMMAND "${CC}" -std=gnu99 -fsyntax-only -I "${OUT}/c" -I "${MATIEC_LIB}/C" "${OUT}/c/PacResource.c"
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "MATIEC's C of the user program does not compile (${rc})")
endif()
