# sources_together(<target> [ALONE <file>...]): the library's .cpp files compiled as one
# translation unit. File by file, each .cpp reads the standard headers and the library's
# own headers again and compiles their inline functions again, which is most of what a
# small engine file costs; together they do that once per library. The objects compute
# the same numbers: -ffp-contract=off and no fast-math fix every rounding, whatever the
# compiler inlines (the expected pictures and `ctest -L identity` check it).
#
# Each file's anonymous namespace becomes one per unit, so two files of a unit must not
# name the same thing in it: a file that does is named under ALONE (its file name, as
# user_control.cpp) and compiled by itself.
#
# It is CMake's unity build, written out by hand for one reason: CMake's unity file
# includes each source by its absolute path, so the same library in a copy of the
# repository (the mutants', the workbench's scratch copies) is a different file to the
# compiler cache, and compiles again. This one includes each source by its path relative
# to the unit, the same in every copy whose build folder lies where the original's does.
# -DPHYSICS_UNITY=OFF (or PHYSICS_UNITY set OFF in a function's scope) compiles file by
# file again.
option(PHYSICS_UNITY "Compile each engine library and common/ as one translation unit" ON)
function(sources_together target)
  cmake_parse_arguments(PARSE_ARGV 1 TOGETHER "" "" "ALONE")
  if(NOT PHYSICS_UNITY)
    return()
  endif()
  get_target_property(sources ${target} SOURCES)
  get_target_property(source_dir ${target} SOURCE_DIR)
  # In a folder of their own: tools find a stage's program as build/<id>_*.
  set(unit_dir ${CMAKE_CURRENT_BINARY_DIR}/together)
  set(unit ${unit_dir}/${target}.cpp)
  set(content "// Made by sources_together (cmake/Together.cmake): ${target}'s files as one unit.\n")
  set(together)
  foreach(source IN LISTS sources)
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY ${source_dir} NORMALIZE OUTPUT_VARIABLE file)
    cmake_path(GET file FILENAME name)
    if(NOT name MATCHES "\\.cpp$" OR name IN_LIST TOGETHER_ALONE)
      continue()
    endif()
    file(RELATIVE_PATH relative ${unit_dir} ${file})
    string(APPEND content "#include \"${relative}\"\n")
    list(APPEND together ${file})
  endforeach()
  file(CONFIGURE OUTPUT ${unit} CONTENT "${content}")
  # The files stay the target's sources (an editor still finds them) but are compiled
  # only through the unit, which the compiler's dependency files tie to each of them.
  set_source_files_properties(${together} PROPERTIES HEADER_FILE_ONLY ON)
  target_sources(${target} PRIVATE ${unit})
endfunction()
