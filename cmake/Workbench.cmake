# add_workbench_stages(): every folder workbench/<X.Y>_<name> (made by tools/workbench,
# then the reader's own) becomes a stage wb_s<X>_<Y>, judged as our s<X>_<Y> is: the same
# features, the same stage tests, our expected pictures. Call it after add_stages.
#
# A reader's stage is work in progress, so nothing of it is in the default build (a
# stage that does not compile never stops `cmake --build build`), and each feature's tests
# are a program of their own: a feature the reader has not written yet fails to compile
# alone, and shows as a failing test that names the book's project, never as a broken
# build or a skipped test. For workbench/3.3_rectangle_collision:
#   wb_s3_3                            target: the program wb_s3_3_rectangle_collision
#   wb_s3_3_test_<feature>, _test_stage  one test program per feature, and the stage's own
#   CTest wb_s3_3.build                builds the program and every test program, each
#                                      alone, and notes which build (cmake/WorkbenchBuild.cmake)
#   CTest wb_s3_3.<feature>, .stage    fail when their program did not build, saying why,
#                                      else run it (cmake/WorkbenchTest.cmake)
#   CTest wb_s3_3.pictures             the default run against our 3.3's expected/
# all labelled wb_s3_3 and workbench. `ctest -L wb_s3_3` builds as it goes.

# The book's projects (stages.txt, through add_stages) as variables BOOK_<sX_Y> holding
# `book project 3.3, "The Rectangle Collision Project" (page 58)`.
function(read_book_projects stages)
  foreach(id IN LISTS stages)
    get_property(heading GLOBAL PROPERTY PHYSICS_STAGE_${id}_PROJECT)
    get_property(page GLOBAL PROPERTY PHYSICS_STAGE_${id}_PAGE)
    string(REGEX REPLACE "^s([0-9]+)_([0-9]+)$" "\\1.\\2" number ${id})
    set(BOOK_${id} "book project ${number}, \"${heading}\" (page ${page})" PARENT_SCOPE)
  endforeach()
endfunction()

function(add_workbench_stages)
  file(GLOB entries LIST_DIRECTORIES true CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/workbench/*)
  get_property(stages GLOBAL PROPERTY PHYSICS_STAGES)
  read_book_projects("${stages}")
  # Which stage a feature first appears in: its test failing sends the reader there.
  foreach(stage IN LISTS stages)
    get_property(features GLOBAL PROPERTY PHYSICS_STAGE_${stage}_FEATURES)
    foreach(feature IN LISTS features)
      if(NOT DEFINED first_stage_of_${feature})
        set(first_stage_of_${feature} ${stage})
      endif()
    endforeach()
  endforeach()

  foreach(folder IN LISTS entries)
    get_filename_component(name ${folder} NAME)
    if(NOT IS_DIRECTORY ${folder} OR name MATCHES "^\\.")  # .making.*: tools/workbench at work
      continue()
    endif()
    if(NOT name MATCHES "^([0-9]+)\\.([0-9]+)(_.*)?$")
      message(WARNING "workbench/${name}: not a stage folder (they are named like 3.3_rectangle_collision); left out")
      continue()
    endif()
    set(stage s${CMAKE_MATCH_1}_${CMAKE_MATCH_2})
    if(NOT stage IN_LIST stages)
      message(WARNING "workbench/${name}: there is no stage ${CMAKE_MATCH_1}.${CMAKE_MATCH_2} to judge it by; left out")
      continue()
    endif()
    if(TARGET wb_${stage})
      message(WARNING "workbench/${name}: a second folder for stage ${CMAKE_MATCH_1}.${CMAKE_MATCH_2}; left out")
      continue()
    endif()
    add_workbench_stage(${stage} ${folder})
  endforeach()
endfunction()

# wb_<stage> from the reader's <folder>, judged by our <stage>'s tests.
function(add_workbench_stage stage folder)
  set(id wb_${stage})
  string(REGEX REPLACE "^s([0-9]+)_([0-9]+)$" "\\1.\\2" number ${stage})
  foreach(key FOLDER PROGRAM CHAPTER FEATURES)
    get_property(${key} GLOBAL PROPERTY PHYSICS_STAGE_${stage}_${key})
  endforeach()
  set(program ${id}_${PROGRAM})
  # The reader's files each compiled alone, not as our engines are (one unit,
  # cmake/Together.cmake): a name two of their files keep in an anonymous namespace must
  # not become an error of the build's.
  set(PHYSICS_UNITY OFF)
  stage_engine_and_program(${id} ${folder} ${PROGRAM} EXCLUDE_FROM_ALL)
  # compare_png too: the reader's loop compares their pictures with ours.
  add_custom_target(${id} DEPENDS ${program} compare_png)

  set(log_dir ${CMAKE_BINARY_DIR}/workbench/${id})
  # What each feature checks, in the book's words (cmake/features.txt): a failure says it first.
  file(STRINGS ${PROJECT_SOURCE_DIR}/cmake/features.txt feature_lines REGEX "^[a-z]")
  foreach(line IN LISTS feature_lines)
    string(REPLACE " | " ";" fields "${line}")
    list(GET fields 0 name)
    list(GET fields 1 whose)
    list(GET fields 2 concept)
    if(whose STREQUAL "ours")
      set(concept "ours, not the book's: ${concept}")
    endif()
    set(concept_of_${name} "${concept}")
  endforeach()
  # Not the chapter's label nor the features': `ctest -L ch3` stays our stages' tests.
  set(labels ${id} workbench)
  set(judged)  # test name, target, what it is, the book project it comes from; 4 per test
  foreach(feature IN LISTS FEATURES)
    set(origin ${first_stage_of_${feature}})
    if(origin STREQUAL stage)
      set(book "${BOOK_${stage}}")
    else()  # older than this stage, whose project can still change what it expects (scene keys)
      set(book "${BOOK_${origin}}, and this stage is ${BOOK_${stage}}")
    endif()
    list(APPEND judged ${feature} ${id}_test_${feature} "${concept_of_${feature}} (feature ${feature})" "${book}")
    add_workbench_tests(${id}_test_${feature} ${PROJECT_SOURCE_DIR}/tests/features/${feature}_test.cpp
      ${stage} ${id} ${program})
  endforeach()
  set(stage_test ${PROJECT_SOURCE_DIR}/tests/stages/${stage}_test.cpp)
  if(EXISTS ${stage_test})
    list(APPEND judged stage ${id}_test_stage "stage ${number}'s own test file (tests/stages/${stage}_test.cpp)" "${BOOK_${stage}}")
    add_workbench_tests(${id}_test_stage ${stage_test} ${stage} ${id} ${program})
  endif()

  set(targets ${program} compare_png)
  set(script ${PROJECT_SOURCE_DIR}/cmake/WorkbenchTest.cmake)
  set(explain "bash;${PROJECT_SOURCE_DIR}/tools/workbench;--explain;${number}")
  list(LENGTH judged left)
  while(left GREATER 0)
    list(POP_FRONT judged test target what book)
    list(APPEND targets ${target})
    if(test STREQUAL "stage")
      set(tag "[#${stage}_test]")
    else()
      set(tag "[#${test}_test]")
    endif()
    add_test(NAME ${id}.${test}
      COMMAND ${CMAKE_COMMAND} -DTEST=${id}.${test} "-DWHAT=${what}" "-DBOOK=${book}"
        -DLOG=${log_dir}/${target} -DPROGRAM=$<TARGET_FILE:${target}> "-DFILTER=${tag}"
        -DVERDICT=${log_dir}/verdicts/${test} "-DEXPLAIN=${explain}" -P ${script})
    # Work in progress can loop for ever: 15 minutes is far more than any of our tests needs.
    set_tests_properties(${id}.${test} PROPERTIES LABELS "${labels}" FIXTURES_REQUIRED ${id} TIMEOUT 900)
    list(LENGTH judged left)
  endwhile()

  add_test(NAME ${id}.pictures
    COMMAND ${CMAKE_COMMAND} -DTEST=${id}.pictures "-DWHAT=the program ${program}" "-DBOOK=${BOOK_${stage}}"
      -DLOG=${log_dir}/${program} -DPROGRAM=$<TARGET_FILE:${program}> -DCOMPARE=$<TARGET_FILE:compare_png>
      -DEXPECTED=${PROJECT_SOURCE_DIR}/${FOLDER}/expected -DACTUAL=${CMAKE_BINARY_DIR}/pictures/${id}
      -DVERDICT=${log_dir}/verdicts/pictures -P ${script})
  set_tests_properties(${id}.pictures PROPERTIES LABELS "${labels}" FIXTURES_REQUIRED ${id} TIMEOUT 900)

  # The engine first, when it has sources: if it does not build, nothing else can.
  get_target_property(engine_type ${id}_engine TYPE)
  set(engine)
  if(engine_type STREQUAL "STATIC_LIBRARY")
    set(engine ${id}_engine)
  endif()
  list(JOIN targets "," target_list)
  add_test(NAME ${id}.build
    COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${CMAKE_BINARY_DIR} "-DGENERATOR=${CMAKE_GENERATOR}"
      -DENGINE=${engine} -DTARGETS=${target_list} -DLOG_DIR=${log_dir} -DSTAGE=${id}
      -P ${PROJECT_SOURCE_DIR}/cmake/WorkbenchBuild.cmake)
  # Two of these at once would run two builds in one build folder: one at a time.
  set_tests_properties(${id}.build PROPERTIES LABELS "${labels}" FIXTURES_SETUP ${id}
    RESOURCE_LOCK workbench_build)
endfunction()

# One test program: <source> against the reader's engine, as our stage's tests are built.
# When its tests run the stage's program (stage_program.h, walkthrough.h), building it
# builds the program too, so that --check never runs a program older than its sources;
# the others do not wait for main.cpp.
function(add_workbench_tests target source stage id program)
  add_executable(${target} EXCLUDE_FROM_ALL ${source})
  stage_test_program(${target} ${stage} ${id}_engine ${program})
  file(READ ${source} text)
  if(text MATCHES "stage_program\\.h|walkthrough\\.h|STAGE_PROGRAM")
    add_dependencies(${target} ${program})
  endif()
  shared_catch_pch(catch_pch)
  target_precompile_headers(${target} REUSE_FROM ${catch_pch})
endfunction()
