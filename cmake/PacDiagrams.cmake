# The timing diagrams of the documentation (docs/diagrams.md). Every scenario/examples/<name>.json with a
# "diagram" object gives docs/diagrams/<name>.json (WaveJSON, pac_scenario --wavedrom) and
# docs/diagrams/<name>.svg, rendered by wavedrom-cli (npm; the versions are pinned by
# cmake/wavedrom/package-lock.json and installed into the build tree). The target `diagrams` rewrites both
# in the source tree; it is not part of ALL and needs Node.js and npm. Every test run checks that the
# committed WaveJSON is still what its scenario gives (tests/scenario/test_diagrams.cpp).
include_guard(GLOBAL)

function(pac_diagrams scenario_target)
  set(docs "${PROJECT_SOURCE_DIR}/docs/diagrams")
  file(GLOB examples CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/scenario/examples/*.json")
  set(names "")
  foreach(example IN LISTS examples)
    file(READ "${example}" text)
    string(JSON diagram ERROR_VARIABLE no_diagram GET "${text}" diagram)
    if(NOT no_diagram)
      get_filename_component(name "${example}" NAME_WE)
      list(APPEND names "${name}")
    endif()
  endforeach()

  find_program(PAC_NPM npm)
  if(NOT PAC_NPM)
    add_custom_target(diagrams
      COMMAND "${CMAKE_COMMAND}" -E echo "diagrams: wavedrom-cli needs Node.js and npm (Debian: apt-get install npm)"
      COMMAND "${CMAKE_COMMAND}" -E false
      VERBATIM)
    return()
  endif()
  set(wavedrom "${PROJECT_SOURCE_DIR}/cmake/wavedrom")
  set(node "${CMAKE_BINARY_DIR}/diagrams-node")
  set(cli "${node}/node_modules/.bin/wavedrom-cli")
  add_custom_command(
    OUTPUT "${cli}"
    COMMAND "${CMAKE_COMMAND}" -E make_directory "${node}"
    COMMAND "${CMAKE_COMMAND}" -E copy "${wavedrom}/package.json" "${wavedrom}/package-lock.json" "${node}"
    COMMAND "${PAC_NPM}" ci --prefix "${node}" --no-audit --no-fund
    DEPENDS "${wavedrom}/package.json" "${wavedrom}/package-lock.json"
    COMMENT "npm: wavedrom-cli into ${node}"
    VERBATIM)
  set(commands "")
  foreach(name IN LISTS names)
    list(APPEND commands COMMAND "${CMAKE_COMMAND}" "-DSCENARIO_BINARY=$<TARGET_FILE:${scenario_target}>"
         "-DWAVEDROM_CLI=${cli}" "-DSCENARIO=${PROJECT_SOURCE_DIR}/scenario/examples/${name}.json"
         "-DOUT=${docs}/${name}" -P "${PROJECT_SOURCE_DIR}/cmake/PacRenderDiagram.cmake")
  endforeach()
  add_custom_target(diagrams ${commands}
    DEPENDS "${cli}" ${scenario_target}
    COMMENT "diagrams: ${names}"
    VERBATIM)
endfunction()
