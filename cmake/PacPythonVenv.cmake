# pac_python_venv(<venv dir> REQUIREMENTS <file> [NO_DEPS <file>]): creates a Python venv and pip-installs
# the pinned packages of REQUIREMENTS, then those of NO_DEPS without their dependencies. It runs at
# configure time, once for each content of the two files.
# Only the first venv of a configure run gets a pip of its own (ensurepip: about 3.5 s of CPU each, on the
# configure's serial path); the others are created without one and filled by that first venv's pip through
# `pip --python` (pip 22.3 or newer). A pip too old for that installs its own into the venv, as before.
# The first venv is made at once (the configure runs the translator from it); the others are made side by
# side in the background, mostly waiting for the package index, and pac_python_venv_wait() at the end of
# the configure waits for them and fails with a venv's pip output if one could not be made (eight venvs one
# after another took 40 s of a fresh clone's configure with the cores idle).
include_guard(GLOBAL)
include("${CMAKE_CURRENT_LIST_DIR}/PacBackgroundJob.cmake")

function(pac_python_venv venv)
  cmake_parse_arguments(ARG "" "REQUIREMENTS;NO_DEPS" "" ${ARGN})
  file(SHA256 "${ARG_REQUIREMENTS}" key)
  if(ARG_NO_DEPS)
    file(SHA256 "${ARG_NO_DEPS}" no_deps_hash)
    string(SHA256 key "${key}${no_deps_hash}")
  endif()
  set(stamp "${venv}/.requirements-${key}")
  get_property(pip_host GLOBAL PROPERTY PAC_PIP_HOST)
  if(EXISTS "${stamp}")
    if(NOT pip_host AND EXISTS "${venv}/bin/pip")
      set_property(GLOBAL PROPERTY PAC_PIP_HOST "${venv}/bin/python")
    endif()
    return()
  endif()
  find_package(Python3 3.9 REQUIRED COMPONENTS Interpreter)
  message(STATUS "creating ${venv} with ${ARG_REQUIREMENTS} ${ARG_NO_DEPS}")
  if(pip_host)
    _pac_python_venv_in_background("${venv}" "${pip_host}" "${stamp}" "${ARG_REQUIREMENTS}" "${ARG_NO_DEPS}")
    return()
  endif()
  execute_process(COMMAND "${Python3_EXECUTABLE}" -m venv "${venv}" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "could not create the venv ${venv} (on Debian: apt-get install python3-venv)")
  endif()
  set(pip "${venv}/bin/python" -m pip install --quiet --disable-pip-version-check)
  set_property(GLOBAL PROPERTY PAC_PIP_HOST "${venv}/bin/python")
  execute_process(COMMAND ${pip} -r "${ARG_REQUIREMENTS}" RESULT_VARIABLE rc)
  if(rc EQUAL 0 AND ARG_NO_DEPS)
    execute_process(COMMAND ${pip} --no-deps -r "${ARG_NO_DEPS}" RESULT_VARIABLE rc)
  endif()
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "pip could not install ${ARG_REQUIREMENTS} ${ARG_NO_DEPS} into ${venv}")
  endif()
  file(GLOB old "${venv}/.requirements-*")
  if(old)
    file(REMOVE ${old})
  endif()
  file(TOUCH "${stamp}")
endfunction()

# A venv made by the first one's pip in a background job: the job writes its exit status into <venv>.job/done.
function(_pac_python_venv_in_background venv pip_host stamp requirements no_deps)
  set(python "${Python3_EXECUTABLE}")
  set(no_deps_line "")
  if(no_deps)
    set(no_deps_line "pip install --quiet --disable-pip-version-check --no-deps -r \"${no_deps}\"")
  endif()
  string(CONFIGURE [=[set -e
venv="@venv@"
"@python@" -m venv --without-pip "$venv"
pip() { "@pip_host@" -m pip --python "$venv/bin/python" "$@"; }
if ! pip --help >/dev/null 2>&1; then  # a pip without --python
  "$venv/bin/python" -m ensurepip --default-pip >/dev/null
  pip() { "$venv/bin/python" -m pip "$@"; }
fi
pip install --quiet --disable-pip-version-check -r "@requirements@"
@no_deps_line@
rm -f "$venv"/.requirements-*
touch "@stamp@"
]=] script @ONLY)
  pac_job_start("${venv}.job" "${script}" "making the venv ${venv}")
  set_property(GLOBAL APPEND PROPERTY PAC_VENV_JOBS "${venv}")
endfunction()

# Waits for the venvs made in the background; a venv that could not be made stops the configure.
function(pac_python_venv_wait)
  get_property(jobs GLOBAL PROPERTY PAC_VENV_JOBS)
  foreach(venv IN LISTS jobs)
    pac_job_wait("${venv}.job" rc log)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "pip could not make the venv ${venv}:\n${log}")
    endif()
  endforeach()
  set_property(GLOBAL PROPERTY PAC_VENV_JOBS "")
endfunction()
