# UserPrograms.LibraryExportsReadBack: the library as pacexport exports it, read back by pacst's user
# mode: the PLCopen XML project (through pacst's PLCopen reader, the one the export's round trip uses)
# and the TwinCAT project (.plcproj with its .TcPOU, .TcGVL and .TcDUT files), each checked as a whole
# program. PACST: the translator command (a ;-list); EXPORT: the export folder; CACHE: pacst's parse
# cache; OUT: a scratch folder for the PLCopen project's ST files.
file(GLOB plcopen "${EXPORT}/*.xml")
file(GLOB twincat "${EXPORT}/twincat/*.plcproj")
list(LENGTH plcopen n_plcopen)
list(LENGTH twincat n_twincat)
if(NOT n_plcopen EQUAL 1 OR NOT n_twincat EQUAL 1)
  message(FATAL_ERROR "expected one PLCopen project and one .plcproj in ${EXPORT} (build the export target)")
endif()
foreach(project IN LISTS plcopen twincat)
  execute_process(COMMAND ${PACST} check --user --cache "${CACHE}" --sources "${OUT}" "${project}"
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "pacst --user refused the library's export ${project}")
  endif()
endforeach()
