# Configure-time jobs run in the background, side by side, mostly waiting for the network (the venvs of
# PacPythonVenv.cmake, CBMC's fetch in PacCbmcFetch.cmake): each in a job folder of its own.
include_guard(GLOBAL)

# pac_job_start(<job folder> <bash script> <what>): runs the script in the background; it writes its exit status
# into <job folder>/done and its output into <job folder>/log. A job that cannot start stops the configure.
function(pac_job_start job script what)
  file(REMOVE_RECURSE "${job}")
  file(MAKE_DIRECTORY "${job}")
  file(WRITE "${job}/run.sh" "${script}")
  execute_process(COMMAND bash -c "(bash '${job}/run.sh'; echo $? > '${job}/done') </dev/null >'${job}/log' 2>&1 &"
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "could not start ${what}")
  endif()
endfunction()

# pac_job_wait(<job folder> <result variable> <log variable>): waits for the job; the result variable is its exit
# status, the log variable its output; the folder is removed.
function(pac_job_wait job result_var log_var)
  execute_process(COMMAND bash -c "while [ ! -s '${job}/done' ]; do sleep 0.1; done; exit $(cat '${job}/done')"
                  RESULT_VARIABLE rc)
  file(READ "${job}/log" log)
  file(REMOVE_RECURSE "${job}")
  set(${result_var} "${rc}" PARENT_SCOPE)
  set(${log_var} "${log}" PARENT_SCOPE)
endfunction()
