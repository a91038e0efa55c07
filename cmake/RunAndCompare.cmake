# Runs a stage's default program into ACTUAL, then checks every picture in EXPECTED
# against the one of the same name in ACTUAL. Used by the <stage>.pictures tests.
# ARGUMENTS (a list, optional) goes to the program first: a stage's second set of
# pictures runs a scene (5.4's pyramid). AFTER (a list, optional) goes after --out: the
# stage program's options when PROGRAM is compare_runs, which passes on what follows --.
# ACTUAL is this test's own folder, and its diff/ below is compare_png's, not the
# program's: a run refuses to replace a folder holding what it did not write, so the
# test clears it first.
# EXPECT=different (optional) turns the test round: it passes only when some picture
# differs (cmake/StrictPictures.cmake: a stage's engine on the next stage's pictures).
# compare_png prints, for each picture, how many pixels differ and the box they are in.
# A program not built yet is said so, with the target that builds it, rather than
# failing with "No such file" (each stage's target builds its program and compare_png).
foreach(needed PROGRAM COMPARE)
  if(NOT EXISTS ${${needed}})
    get_filename_component(target ${${needed}} NAME)
    message(FATAL_ERROR "${${needed}} is not built: cmake --build <build folder> --target ${target}")
  endif()
endforeach()
file(REMOVE_RECURSE ${ACTUAL})
execute_process(COMMAND ${PROGRAM} ${ARGUMENTS} --out ${ACTUAL} ${AFTER} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} exited with status ${status}")
endif()
execute_process(COMMAND ${COMPARE} ${EXPECTED} ${ACTUAL} --diff-dir ${ACTUAL}/diff RESULT_VARIABLE status)
if(EXPECT STREQUAL "different")
  if(status EQUAL 0)
    message(FATAL_ERROR "${PROGRAM} draws every picture of ${EXPECTED}: "
      "the pictures test cannot tell its engine from the stage's")
  elseif(NOT status EQUAL 1)
    message(FATAL_ERROR "compare_png could not compare the pictures (status ${status})")
  endif()
elseif(NOT status EQUAL 0)
  set(where "the run's pictures are in ${ACTUAL}")
  if(IS_DIRECTORY ${ACTUAL}/diff)
    string(APPEND where ", the differences in red in ${ACTUAL}/diff")
  endif()
  message(FATAL_ERROR "pictures differ from ${EXPECTED} (above: which, and by how much); ${where}")
endif()
