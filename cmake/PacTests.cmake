# pac_gtest_tests(<test program> [TEST_FILTER <gtest filter>] [SHARDS <n>]): registers the GoogleTest cases of a
# test program with CTest; SHARDS: the shard count of this program where PAC_TEST_SHARDS is not 0.
#
# PAC_TEST_SHARDS=0 (the default preset): one CTest test per case (gtest_discover_tests), so a failure
# names its case in CTest's summary. PAC_TEST_SHARDS=N: N CTest tests per program, each running every
# N-th case in one process (GoogleTest's own sharding), which is what the sanitizer preset does: there a
# process costs about 0.4 s of CPU before and after its cases (ASan's start, gcov writing its counters at
# exit) against milliseconds for most cases, so one process per case was most of the preset's test time
# (docs/measurements/build_time_log.md). Every case still runs, and a failing case is named in its shard's output.
include_guard(GLOBAL)
include(GoogleTest)

set(PAC_TEST_SHARDS 0 CACHE STRING "CTest tests per GoogleTest program (0: one per case)")

function(pac_gtest_tests program)
  cmake_parse_arguments(ARG "" "TEST_FILTER;SHARDS" "" ${ARGN})
  if(PAC_TEST_SHARDS LESS_EQUAL 0)
    if(ARG_TEST_FILTER)
      gtest_discover_tests(${program} DISCOVERY_TIMEOUT 60 TEST_FILTER "${ARG_TEST_FILTER}")
    else()
      gtest_discover_tests(${program} DISCOVERY_TIMEOUT 60)
    endif()
    return()
  endif()
  set(filter "")
  if(ARG_TEST_FILTER)
    set(filter "--gtest_filter=${ARG_TEST_FILTER}")
  endif()
  set(shards ${PAC_TEST_SHARDS})
  if(ARG_SHARDS)
    set(shards ${ARG_SHARDS})
  endif()
  math(EXPR last "${shards} - 1")
  foreach(index RANGE ${last})
    set(name "${program}.shard${index}of${shards}")
    add_test(NAME "${name}" COMMAND ${program} ${filter})
    set_tests_properties("${name}" PROPERTIES
      ENVIRONMENT "GTEST_TOTAL_SHARDS=${shards};GTEST_SHARD_INDEX=${index}")
  endforeach()
endfunction()
