# add_stages(<list>): add_stage for every stage of the list (stages.txt at the top, which
# says how it is written), oldest first. A line it cannot read stops the configuration
# with the file, the line number and what is wrong. Each stage's facts are remembered as
# global properties (below), the list's book facts as PHYSICS_STAGE_<id>_<PROJECT|PAGE>,
# and the stages the bench drives, oldest first, as PHYSICS_BENCH_STAGES.
function(add_stages list)
  # Configure again when the list changes: file(STRINGS) alone would not.
  set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${list})
  file(STRINGS ${list} lines)
  set(number 0)
  set(folder)
  set(features)  # every feature so far: a stage keeps those of the stages before
  foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    if(line MATCHES "^#" OR line MATCHES "^[ \t]*$")
      continue()
    elseif(line MATCHES "^[^ \t]")
      if(folder)
        add_listed_stage(${folder} "${features}" "${project}" "${page}" "${bench}")
      endif()
      set(folder "${line}")
      foreach(key project page read bench)
        set(${key})
      endforeach()
      set(chapter_agrees FALSE)
      if(folder MATCHES "^ch([0-9]+)_[a-z0-9_]+/([0-9]+)\\.([0-9]+)_[a-z0-9_]+$")
        if(CMAKE_MATCH_1 EQUAL CMAKE_MATCH_2)
          set(chapter_agrees TRUE)
        endif()
      endif()
      if(NOT chapter_agrees)
        message(FATAL_ERROR "${list}:${number}: \"${folder}\" is not a stage folder (chN_<name>/N.M_<name>)")
      endif()
      if(NOT IS_DIRECTORY ${PROJECT_SOURCE_DIR}/${folder})
        message(FATAL_ERROR "${list}:${number}: there is no folder ${folder}")
      endif()
    elseif(NOT folder)
      message(FATAL_ERROR "${list}:${number}: a stage's fact before its folder")
    elseif(line MATCHES "^[ \t]+features[ \t]+(.+)$")
      string(REGEX REPLACE "[ \t]+" ";" added "${CMAKE_MATCH_1}")
      list(APPEND features ${added})
    elseif(line MATCHES "^[ \t]+(project|page|read|bench)[ \t]+(.+)$")
      set(${CMAKE_MATCH_1} "${CMAKE_MATCH_2}")
    else()
      message(FATAL_ERROR "${list}:${number}: expected \"key  value\" with a key of project, page, read, features, bench")
    endif()
  endforeach()
  if(folder)
    add_listed_stage(${folder} "${features}" "${project}" "${page}" "${bench}")
  endif()
endfunction()

# One stage of the list: the folder ch3_collision/3.3_rectangle_collision is stage s3_3,
# program rectangle_collision, chapter ch3.
function(add_listed_stage folder features project page bench)
  string(REGEX MATCH "^(ch[0-9]+)_[^/]*/([0-9]+)\\.([0-9]+)_(.*)$" matched ${folder})
  set(id s${CMAKE_MATCH_2}_${CMAKE_MATCH_3})
  add_stage(${id} FOLDER ${folder} PROGRAM ${CMAKE_MATCH_4} CHAPTER ${CMAKE_MATCH_1} FEATURES ${features})
  set_property(GLOBAL PROPERTY PHYSICS_STAGE_${id}_PROJECT "${project}")
  set_property(GLOBAL PROPERTY PHYSICS_STAGE_${id}_PAGE "${page}")
  if(bench STREQUAL "yes")
    set_property(GLOBAL APPEND PROPERTY PHYSICS_BENCH_STAGES ${id})
  elseif(bench)
    message(FATAL_ERROR "stages.txt, ${folder}: bench is \"yes\" or left out (got \"${bench}\")")
  endif()
endfunction()

# add_stage(<id> FOLDER <dir> PROGRAM <name> CHAPTER <chN> [FEATURES <feature>...])
#
# Makes everything one book project needs from its folder:
#   <id>_engine        library: every .cpp of the folder but main.cpp (the book's engine files)
#   <id>_<name>        program: main.cpp, the stage's index.html
#   <id>_tests         tests/features/<feature>_test.cpp for each listed feature, compiled
#                      against this folder's headers, plus tests/stages/<id>_test.cpp
#                      (only when Catch2 was found: PHYSICS_TESTS)
#   <id>               builds the three above and compare_png, all that the tests
#                      labelled <id> run: `cmake --build build --target <id>`, then
#                      `ctest --test-dir build -L '^<id>$'`
# and registers with CTest, all labelled <id> and <chN>:
#   <id>.<feature>     one test per feature file, also labelled <feature>
#   <id>.stage         the stage's own tests
#   <id>.pictures      runs the default program and compares its pictures with expected/
#   <id>.overlay_pictures  when expected/overlay/ exists: the same run with --overlay,
#                      compared with expected/overlay/ (labels also pictures and overlay)
#   <id>.names         when names.md exists: the name map's check (label names; that the
#                      check can fail is tested once, names.checker_sees_renames)
#   <id>.readme_keys   with them: the README's Keys table against --help's key list
#
# Each call is also remembered (global properties PHYSICS_STAGES and
# PHYSICS_STAGE_<id>_<FOLDER|PROGRAM|CHAPTER|FEATURES>), so that cmake/Workbench.cmake
# can build a reader's own copy of the stage and judge it by the same tests.
function(add_stage id)
  cmake_parse_arguments(PARSE_ARGV 1 STAGE "" "FOLDER;PROGRAM;CHAPTER" "FEATURES")
  # Every feature says in cmake/features.txt what it checks, in the book's words, and
  # whether it is the book's or ours: the workbench names a reader's checks by it.
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/cmake/features.txt)
  file(STRINGS ${PROJECT_SOURCE_DIR}/cmake/features.txt described REGEX "^[a-z_]+ [|] (book|ours) [|] .")
  list(TRANSFORM described REPLACE " [|] .*" "")
  foreach(feature IN LISTS STAGE_FEATURES)
    if(NOT feature IN_LIST described)
      message(FATAL_ERROR "add_stage(${id}): feature ${feature} has no line in cmake/features.txt "
                          "(${feature} | book or ours | what it checks, in the book's words)")
    endif()
  endforeach()
  set_property(GLOBAL APPEND PROPERTY PHYSICS_STAGES ${id})
  foreach(key FOLDER PROGRAM CHAPTER FEATURES)
    set_property(GLOBAL PROPERTY PHYSICS_STAGE_${id}_${key} "${STAGE_${key}}")
  endforeach()
  set(dir ${PROJECT_SOURCE_DIR}/${STAGE_FOLDER})

  stage_engine_and_program(${id} ${dir} ${STAGE_PROGRAM})
  set(program ${id}_${STAGE_PROGRAM})

  set(labels ${id} ${STAGE_CHAPTER})
  if(PHYSICS_TESTS)  # Catch2 found (top-level CMakeLists.txt)
    stage_test_sources(test_sources ${id} ${STAGE_FEATURES})
    shared_catch_pch(catch_pch)
    add_executable(${id}_tests ${test_sources})
    stage_test_program(${id}_tests ${id} ${id}_engine ${program})
    # Every test file includes Catch2's 17,000-line header: parse it once for every stage.
    target_precompile_headers(${id}_tests REUSE_FROM ${catch_pch})
    test_files_together(${id}_tests)
    # Some tests run the program (--help, scene files, dumps): building the tests builds
    # it, so they never run one older than its sources.
    add_dependencies(${id}_tests ${program})
    add_custom_target(${id})
    add_dependencies(${id} ${program} ${id}_tests compare_png)

    foreach(feature IN LISTS STAGE_FEATURES)
      add_test(NAME ${id}.${feature} COMMAND ${id}_tests "-#" "[#${feature}_test]")
      set_tests_properties(${id}.${feature} PROPERTIES LABELS "${labels};${feature}")
    endforeach()
    if(EXISTS ${PROJECT_SOURCE_DIR}/tests/stages/${id}_test.cpp)
      add_test(NAME ${id}.stage COMMAND ${id}_tests "-#" "[#${id}_test]")
      set_tests_properties(${id}.stage PROPERTIES LABELS "${labels};stage")
    endif()
  else()
    add_custom_target(${id})
    add_dependencies(${id} ${program} compare_png)
  endif()

  add_test(NAME ${id}.pictures
    COMMAND ${CMAKE_COMMAND}
      -DPROGRAM=$<TARGET_FILE:${program}>
      -DCOMPARE=$<TARGET_FILE:compare_png>
      -DEXPECTED=${dir}/expected
      -DACTUAL=${CMAKE_BINARY_DIR}/pictures/${id}
      -P ${PROJECT_SOURCE_DIR}/cmake/RunAndCompare.cmake)
  set_tests_properties(${id}.pictures PROPERTIES LABELS "${labels};pictures")

  # names.md, the book's names against ours: each C++ name it gives is where it says
  # (tests/names/).
  if(EXISTS ${dir}/names.md)
    set(check_names ${PROJECT_SOURCE_DIR}/tests/names/check_name_map.sh)
    add_test(NAME ${id}.names COMMAND bash ${check_names} ${dir})
    # The README's Keys table, which links names.md, is the key list of --help
    # (stage_keys_test checks that list against what the keys do).
    add_test(NAME ${id}.readme_keys
      COMMAND bash ${PROJECT_SOURCE_DIR}/tests/names/check_readme_keys.sh $<TARGET_FILE:${program}> ${dir}/README.md)
    set_tests_properties(${id}.names ${id}.readme_keys PROPERTIES LABELS "${labels};names")
  endif()

  if(EXISTS ${dir}/expected/overlay)
    add_test(NAME ${id}.overlay_pictures
      COMMAND ${CMAKE_COMMAND}
        -DPROGRAM=$<TARGET_FILE:${program}>
        -DARGUMENTS=--overlay
        -DCOMPARE=$<TARGET_FILE:compare_png>
        -DEXPECTED=${dir}/expected/overlay
        -DACTUAL=${CMAKE_BINARY_DIR}/pictures/${id}_overlay
        -P ${PROJECT_SOURCE_DIR}/cmake/RunAndCompare.cmake)
    set_tests_properties(${id}.overlay_pictures PROPERTIES LABELS "${labels};pictures;overlay")
  endif()
endfunction()

# <target>_engine (every .cpp of <dir> but main.cpp) and the program <target>_<name>
# (main.cpp). Extra arguments go to add_library and add_executable (EXCLUDE_FROM_ALL).
# A folder with nothing but main.cpp (a reader's 1.1 as it starts) has an engine of
# headers only.
set(PHYSICS_ENGINE_FILES_ALONE user_control.cpp contact_overlay.cpp)
function(stage_engine_and_program target dir name)
  file(GLOB engine_sources CONFIGURE_DEPENDS ${dir}/*.cpp)
  list(REMOVE_ITEM engine_sources ${dir}/main.cpp)
  if(engine_sources)
    add_library(${target}_engine STATIC ${ARGN} ${engine_sources})
    target_include_directories(${target}_engine PUBLIC ${dir})
    # One translation unit (cmake/Together.cmake), but for the files whose anonymous
    # namespace names what another file's does with another value: user_control.cpp's
    # kSideMin (my_game.cpp's), contact_overlay.cpp's kNormalColor (overlay.cpp's).
    sources_together(${target}_engine ALONE ${PHYSICS_ENGINE_FILES_ALONE})
    target_link_libraries(${target}_engine PUBLIC browser)
  else()
    add_library(${target}_engine INTERFACE)
    target_include_directories(${target}_engine INTERFACE ${dir})
    target_link_libraries(${target}_engine INTERFACE browser)
  endif()
  add_executable(${target}_${name} ${ARGN} ${dir}/main.cpp)
  target_link_libraries(${target}_${name} PRIVATE ${target}_engine)
endfunction()

# The test sources of stage <id> into <out>: tests/features/<feature>_test.cpp for each
# feature, then tests/stages/<id>_test.cpp when there is one.
function(stage_test_sources out id)
  set(sources)
  foreach(feature IN LISTS ARGN)
    list(APPEND sources ${PROJECT_SOURCE_DIR}/tests/features/${feature}_test.cpp)
  endforeach()
  if(EXISTS ${PROJECT_SOURCE_DIR}/tests/stages/${id}_test.cpp)
    list(APPEND sources ${PROJECT_SOURCE_DIR}/tests/stages/${id}_test.cpp)
  endif()
  set(${out} ${sources} PARENT_SCOPE)
endfunction()

# What a test program of stage <id> needs: the engine it judges, the oracle, Catch2's
# main, the test support headers, and the facts the tests ask for (STAGE_ID names the
# stage whose behaviour is expected, STAGE_PROGRAM the program to run).
function(stage_test_program target id engine program)
  test_optimization(${target})
  # oracle/: the collision oracle the tests judge the engine by (shared with the bench).
  target_link_libraries(${target} PRIVATE ${engine} oracle catch2_main)
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/tests/support)
  target_compile_definitions(${target} PRIVATE
    STAGE_ID="${id}" STAGE_PROGRAM="$<TARGET_FILE:${program}>"
    SCENE_LIBRARY_DIR="${PROJECT_SOURCE_DIR}/ch5_demo/scenes"
    BENCH_SCENES_DIR="${PROJECT_SOURCE_DIR}/bench/scenes")
endfunction()

# A stage's test files compiled together, as one translation unit (CMake's unity build).
# File by file, each reads the precompiled Catch2 header, the stage's headers and the test
# support headers again and compiles their inline functions again, which is most of what a
# test file costs; together they do that once: 5.4's 30 test files take 28 CPU s instead
# of 112 (g++ 12, from scratch). Each test file keeps its own names in a namespace named after
# it (movement_test, s5_4_test), so two files' kDt or demoWorld never meet.
# -DPHYSICS_TEST_FILES_PER_UNIT=1 compiles each file alone again, the quicker rebuild while
# one test file is being edited (any other number: that many files a unit).
set(PHYSICS_TEST_FILES_PER_UNIT 0 CACHE STRING
  "Test files per translation unit of a stage's test program (0: all of them, 1: each alone)")
function(test_files_together target)
  if(NOT PHYSICS_TEST_FILES_PER_UNIT EQUAL 1)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${PHYSICS_TEST_FILES_PER_UNIT})
  endif()
endfunction()

# The tests check, the engine computes: the engine keeps the build's -O3, the test files
# (Catch2's macros, most of a full build's compile time) take -O1, which compiles them in
# two thirds of the time and cannot change a result: the numbers they check come from the
# engine, and -ffp-contract=off keeps every level's doubles the same. A target that
# shares its precompiled header with test programs takes it too (the flags must match).
function(test_optimization target)
  target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:-O1>)
endfunction()

# The name of the target whose precompiled Catch2 header every stage's test programs (and
# the workbench's) reuse, made on first use. Its flags are theirs: GCC takes a
# precompiled header only when the options match, and otherwise reads the header again.
function(shared_catch_pch out)
  if(NOT TARGET catch_pch)
    set(source ${CMAKE_BINARY_DIR}/catch_pch.cpp)
    file(CONFIGURE OUTPUT ${source} CONTENT "// Builds the precompiled Catch2 header the test programs share.\n")
    add_library(catch_pch OBJECT EXCLUDE_FROM_ALL ${source})
    target_link_libraries(catch_pch PRIVATE Catch2::Catch2)
    target_precompile_headers(catch_pch PRIVATE <catch2/catch.hpp>)
    test_optimization(catch_pch)
  endif()
  set(${out} catch_pch PARENT_SCOPE)
endfunction()
