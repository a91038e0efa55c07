# add_stage(<id> FOLDER <dir> PROGRAM <name> CHAPTER <chN> [FEATURES <feature>...])
#
# Makes everything one book project needs from its folder:
#   <id>_engine        library: every .cpp of the folder but main.cpp (the book's engine files)
#   <id>_<name>        program: main.cpp, the stage's index.html
#   <id>_tests         tests/features/<feature>_test.cpp for each listed feature, compiled
#                      against this folder's headers, plus tests/stages/<id>_test.cpp
#   <id>               builds the three above: `cmake --build build --target <id>`
# and registers with CTest, all labelled <id> and <chN>:
#   <id>.<feature>     one test per feature file, also labelled <feature>
#   <id>.stage         the stage's own tests
#   <id>.pictures      runs the default program and compares its pictures with expected/
function(add_stage id)
  cmake_parse_arguments(PARSE_ARGV 1 STAGE "" "FOLDER;PROGRAM;CHAPTER" "FEATURES")
  set(dir ${PROJECT_SOURCE_DIR}/${STAGE_FOLDER})

  file(GLOB engine_sources CONFIGURE_DEPENDS ${dir}/*.cpp)
  list(REMOVE_ITEM engine_sources ${dir}/main.cpp)
  add_library(${id}_engine STATIC ${engine_sources})
  target_include_directories(${id}_engine PUBLIC ${dir})
  target_link_libraries(${id}_engine PUBLIC browser)

  set(program ${id}_${STAGE_PROGRAM})
  add_executable(${program} ${dir}/main.cpp)
  target_link_libraries(${program} PRIVATE ${id}_engine)

  set(test_sources)
  foreach(feature IN LISTS STAGE_FEATURES)
    list(APPEND test_sources ${PROJECT_SOURCE_DIR}/tests/features/${feature}_test.cpp)
  endforeach()
  set(stage_test ${PROJECT_SOURCE_DIR}/tests/stages/${id}_test.cpp)
  if(EXISTS ${stage_test})
    list(APPEND test_sources ${stage_test})
  endif()
  add_executable(${id}_tests ${test_sources})
  # oracle/: the collision oracle the tests judge the engine by (shared with the bench).
  target_link_libraries(${id}_tests PRIVATE ${id}_engine oracle catch2_main)
  target_include_directories(${id}_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests/support)
  # Every test file includes Catch2's 17,000-line header: parse it once per executable.
  target_precompile_headers(${id}_tests PRIVATE <catch2/catch.hpp>)
  target_compile_definitions(${id}_tests PRIVATE
    STAGE_ID="${id}" STAGE_PROGRAM="$<TARGET_FILE:${program}>"
    SCENE_LIBRARY_DIR="${PROJECT_SOURCE_DIR}/ch5_demo/scenes"
    BENCH_SCENES_DIR="${PROJECT_SOURCE_DIR}/bench/scenes")

  add_custom_target(${id} DEPENDS ${program} ${id}_tests)

  set(labels ${id} ${STAGE_CHAPTER})
  foreach(feature IN LISTS STAGE_FEATURES)
    add_test(NAME ${id}.${feature} COMMAND ${id}_tests "-#" "[#${feature}_test]")
    set_tests_properties(${id}.${feature} PROPERTIES LABELS "${labels};${feature}")
  endforeach()
  if(EXISTS ${stage_test})
    add_test(NAME ${id}.stage COMMAND ${id}_tests "-#" "[#${id}_test]")
    set_tests_properties(${id}.stage PROPERTIES LABELS "${labels};stage")
  endif()

  add_test(NAME ${id}.pictures
    COMMAND ${CMAKE_COMMAND}
      -DPROGRAM=$<TARGET_FILE:${program}>
      -DCOMPARE=$<TARGET_FILE:compare_png>
      -DEXPECTED=${dir}/expected
      -DACTUAL=${CMAKE_BINARY_DIR}/pictures/${id}
      -P ${PROJECT_SOURCE_DIR}/cmake/RunAndCompare.cmake)
  set_tests_properties(${id}.pictures PROPERTIES LABELS "${labels};pictures")
endfunction()
