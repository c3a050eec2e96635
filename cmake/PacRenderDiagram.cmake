# One diagram of the documentation: SCENARIO's "diagram" as WaveJSON (OUT.json, by SCENARIO_BINARY) and
# as SVG (OUT.svg, by WAVEDROM_CLI). Run by the target `diagrams` (cmake/PacDiagrams.cmake).
execute_process(COMMAND "${SCENARIO_BINARY}" --wavedrom "${OUT}.json" "${SCENARIO}"
                OUTPUT_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${SCENARIO}: pac_scenario exited with ${rc} (run it to see why)")
endif()
execute_process(COMMAND "${WAVEDROM_CLI}" -i "${OUT}.json" -s "${OUT}.svg" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "wavedrom-cli could not render ${OUT}.json")
endif()
message(STATUS "diagram ${OUT}.svg")
