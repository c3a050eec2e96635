# CBMC 6.6.0's private root (tests/cbmc/fetch_cbmc.sh), fetched in the background: the download from Debian's
# archive (about 10 s, mostly waiting for the network) runs beside the first venv and the library's translation
# at configure time instead of after them. tests/cbmc waits for it where it used to fetch, and a failed fetch
# stops the configure there with the script's output, as before.
set(PAC_CBMC_ROOT "${PROJECT_SOURCE_DIR}/build/cbmc-root" CACHE PATH "CBMC's private root (tests/cbmc/fetch_cbmc.sh)")
include("${CMAKE_CURRENT_LIST_DIR}/PacBackgroundJob.cmake")
set(_pac_cbmc_job "${PROJECT_BINARY_DIR}/cbmc-fetch.job")

# Starts fetch_cbmc.sh into PAC_CBMC_ROOT.
function(pac_cbmc_fetch_start)
  pac_job_start("${_pac_cbmc_job}" "bash '${PROJECT_SOURCE_DIR}/tests/cbmc/fetch_cbmc.sh' '${PAC_CBMC_ROOT}'\n"
                "fetching CBMC into ${PAC_CBMC_ROOT} (tests/cbmc/fetch_cbmc.sh)")
endfunction()

# Waits for the fetch, if one is under way; its output becomes the configure's, and a failure stops the configure.
function(pac_cbmc_fetch_wait)
  if(NOT EXISTS "${_pac_cbmc_job}")
    return()
  endif()
  pac_job_wait("${_pac_cbmc_job}" rc log)
  string(STRIP "${log}" log)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "could not fetch CBMC into ${PAC_CBMC_ROOT} (tests/cbmc/fetch_cbmc.sh):\n${log}\n"
                        "-DPAC_CBMC=OFF leaves the model-checking harnesses out")
  endif()
  if(log)
    message(STATUS "${log}")
  endif()
endfunction()
