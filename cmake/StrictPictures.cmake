# add_strict_picture_tests(): the proof that the pictures tests are strict. A reader who
# starts 3.4 from a copy of our 3.3 (tools/workbench 3.4) and writes nothing yet must not
# pass 3.4's pictures; so for every pair of stages in the book's order, from 1.1 and 2.1
# up to 4.4 and 5.1, the engine of the first draws the default run of the second, and its
# pictures must differ from the second's expected ones. Call it after add_stages.
#   <first>_on_<second>                 program: our <first>'s main.cpp and engine, with
#                                       <second>'s default run (cmake/DefaultRun.cmake),
#                                       just as the reader's copy starts
#   CTest strict.<first>_on_<second>    runs it; passes when compare_png finds a picture
#                                       that differs, and prints where
# all labelled strict_pictures (target strict_pictures builds the programs; the default
# build does too). The stages after 5.1 draw 5.1's pictures on purpose, so the pairs end
# at 5.1: 5.2's identity with 5.1 is a feature, not slack.
include(${CMAKE_CURRENT_LIST_DIR}/DefaultRun.cmake)

function(add_strict_picture_tests)
  get_property(stages GLOBAL PROPERTY PHYSICS_STAGES)
  set(last_pair_ends_at s5_1)
  set(programs)
  set(first)
  foreach(second IN LISTS stages)
    if(first)
      add_strict_picture_test(${first} ${second})
      list(APPEND programs ${first}_on_${second})
    endif()
    if(second STREQUAL last_pair_ends_at)
      break()
    endif()
    set(first ${second})
  endforeach()
  add_custom_target(strict_pictures DEPENDS ${programs} compare_png)
endfunction()

function(add_strict_picture_test first second)
  foreach(stage first second)
    get_property(folder GLOBAL PROPERTY PHYSICS_STAGE_${${stage}}_FOLDER)
    set(${stage}_dir ${PROJECT_SOURCE_DIR}/${folder})
  endforeach()
  set(program ${first}_on_${second})
  set(main ${CMAKE_BINARY_DIR}/strict_pictures/${program}_main.cpp)
  graft_default_run(${main} ${first_dir}/main.cpp ${second_dir}/main.cpp ${program})
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${first_dir}/main.cpp ${second_dir}/main.cpp)
  add_executable(${program} ${main})
  target_link_libraries(${program} PRIVATE ${first}_engine)

  add_test(NAME strict.${program}
    COMMAND ${CMAKE_COMMAND}
      -DPROGRAM=$<TARGET_FILE:${program}>
      -DCOMPARE=$<TARGET_FILE:compare_png>
      -DEXPECTED=${second_dir}/expected
      -DACTUAL=${CMAKE_BINARY_DIR}/pictures/${program}
      -DEXPECT=different
      -P ${PROJECT_SOURCE_DIR}/cmake/RunAndCompare.cmake)
  set_tests_properties(strict.${program} PROPERTIES LABELS "strict_pictures")
endfunction()
