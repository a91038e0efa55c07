# One test of a workbench stage (cmake/Workbench.cmake), run after <stage>.build
# (cmake/WorkbenchBuild.cmake) has tried to build its program. It fails, naming the
# book's project to read, when the program did not build; otherwise it runs the tests
# (FILTER, a Catch2 tag) or the default run whose pictures it compares (COMPARE).
#   -DTEST= -DWHAT= -DBOOK= -DLOG=<log dir>/<target> -DPROGRAM= -DVERDICT=<file>
#   [-DEXPLAIN=<command>: prints a build log's first error in the book's words]
#   then -DFILTER=   or   -DCOMPARE= -DEXPECTED= -DACTUAL=
# VERDICT gets "passed" or "failed", which tools/workbench --list reads (as --check
# writes it too), so that listing the stages runs nothing.
# The reason, first and as it is (FATAL_ERROR would rewrap it), then the failure.
function(fail text)
  file(WRITE ${VERDICT} "failed\n")
  message(NOTICE "${TEST}: ${text}")
  message(FATAL_ERROR "${TEST} failed")
endfunction()

if(NOT EXISTS ${LOG}.status)
  string(REGEX REPLACE "\\..*" ".build" builder ${TEST})
  fail("not built yet: run it with ctest, whose test ${builder} builds it first")
endif()
file(READ ${LOG}.status status)
if(NOT status EQUAL 0)
  # The first error is the one to fix first; a link error has no "error:" but says what is missing.
  file(STRINGS ${LOG}.log errors ENCODING UTF-8 REGEX "error:|undefined reference|multiple definition")
  if(errors)
    list(GET errors 0 first_error)
  else()
    set(first_error "(none found: see the build's words)")
  endif()
  if(status STREQUAL "engine")
    set(WHAT "${WHAT} waits for your engine, which does not build yet")
  else()
    set(WHAT "${WHAT} does not build yet")
  endif()
  # Which of the book's names the error is about (tools/workbench --explain, names.md).
  set(explained "")
  if(DEFINED EXPLAIN)
    execute_process(COMMAND ${EXPLAIN} ${LOG}.log OUTPUT_VARIABLE explained ERROR_QUIET)
    string(REGEX REPLACE "\n$" "" explained "${explained}")
    string(REPLACE "\n" "\n  " explained "${explained}")
    if(explained)
      set(explained "\n  ${explained}")
    endif()
  endif()
  fail("${WHAT}; it comes from ${BOOK}.
  first error: ${first_error}${explained}
  everything the build said: ${LOG}.log")
endif()

if(DEFINED COMPARE)
  file(REMOVE_RECURSE ${ACTUAL})  # no pictures of an earlier run can pass for this one's
  execute_process(COMMAND ${PROGRAM} --out ${ACTUAL} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    fail("${WHAT} exited with status ${status}; it comes from ${BOOK}")
  endif()
  execute_process(COMMAND ${COMPARE} ${EXPECTED} ${ACTUAL} --diff-dir ${ACTUAL}/diff RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    set(where "yours are in ${ACTUAL}")
    if(IS_DIRECTORY ${ACTUAL}/diff)
      string(APPEND where ", the differences in red in ${ACTUAL}/diff")
    endif()
    fail("the pictures of ${WHAT} differ from ours in ${EXPECTED} (above: by how much;
  ${where}); they come from ${BOOK}")
  endif()
else()
  execute_process(COMMAND ${PROGRAM} "-#" ${FILTER} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    fail("${WHAT} fails (the checks above say where); it comes from ${BOOK}")
  endif()
endif()
file(WRITE ${VERDICT} "passed\n")
