# compare_runs with settings it or the stage must refuse: each run ends with exit status
# 2, exactly one line on stderr, and no output folder. Used by the compare_runs.refusal
# test (PROGRAM, STAGE, SCENE, OUT).
function(expect_refusal what)
  file(REMOVE_RECURSE ${OUT})
  execute_process(COMMAND ${PROGRAM} ${STAGE} ${SCENE} ${ARGN} --out ${OUT} -- --frames 2
                  RESULT_VARIABLE status ERROR_VARIABLE complaint OUTPUT_QUIET)
  string(REGEX MATCHALL "\n" breaks "${complaint}")
  list(LENGTH breaks lines)
  if(NOT status EQUAL 2 OR NOT lines EQUAL 1 OR EXISTS ${OUT})
    message(FATAL_ERROR "${what}: status ${status}, ${lines} lines: ${complaint}")
  endif()
  message(STATUS "${what}: ${complaint}")
endfunction()

expect_refusal("a key the stage does not know" "{\"solver\": \"book\"}" "{\"solverr\": \"book\"}")
expect_refusal("a value the stage refuses" "{\"velocity_iterations\": 0}" "{}")
expect_refusal("a setting that is not JSON" "{solver: book}" "{}")
expect_refusal("an option compare_runs sets itself" "{}" "{}" -- --scene x.json)
