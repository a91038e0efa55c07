# Runs a stage's default program into ACTUAL, then checks every picture in EXPECTED
# against the one of the same name in ACTUAL. Used by the <stage>.pictures tests.
# ARGUMENTS (a list, optional) goes to the program first: a stage's second set of
# pictures runs a scene (5.4's pyramid). AFTER (a list, optional) goes after --out: the
# stage program's options when PROGRAM is compare_runs, which passes on what follows --.
# ACTUAL is this test's own folder, and its diff/ below is compare_png's, not the
# program's: a run refuses to replace a folder holding what it did not write, so the
# test clears it first.
file(REMOVE_RECURSE ${ACTUAL})
execute_process(COMMAND ${PROGRAM} ${ARGUMENTS} --out ${ACTUAL} ${AFTER} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} exited with status ${status}")
endif()
execute_process(COMMAND ${COMPARE} ${EXPECTED} ${ACTUAL} --diff-dir ${ACTUAL}/diff RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "pictures differ from ${EXPECTED}; see ${ACTUAL}/diff")
endif()
