# graft_default_run(<out> <copy> <ours> <id>) writes to <out> the main.cpp <copy> with
# the default run of the main.cpp <ours> in place of its own: the block
# `const browser::StageDefaults kStage{ ... };` with the comment just above it (the key
# presses, frames and pictures of the run, and what they show), its `.id` made <id>.
# The default run is page, not engine: with it, the engine of one stage draws the
# pictures of another. tools/workbench gives a reader's copy of the stage before X.Y the
# default run of our X.Y this way, and cmake/StrictPictures.cmake each stage's engine
# the next stage's. <out> is written only when its text changes, so nothing rebuilds
# for nothing.
#
# As a script: cmake -DOUT= -DCOPY= -DOURS= -DID= -P cmake/DefaultRun.cmake

# The default run of main.cpp text <text>: <before>, <block> and <after> it.
function(split_default_run text before block after)
  string(FIND "${text}" "const browser::StageDefaults kStage{" start)
  if(start EQUAL -1)
    set(${block} "" PARENT_SCOPE)
    return()
  endif()
  string(SUBSTRING "${text}" 0 ${start} head)
  # The comment lines just above it belong to it: they say what the run shows.
  string(REGEX MATCH "\n((//[^\n]*\n)*)$" comment "${head}")
  string(LENGTH "${CMAKE_MATCH_1}" comment_length)
  math(EXPR first "${start} - ${comment_length}")
  string(SUBSTRING "${text}" ${start} -1 rest)
  string(FIND "${rest}" "\n};\n" end)
  if(end EQUAL -1)
    set(${block} "" PARENT_SCOPE)
    return()
  endif()
  math(EXPR last "${start} + ${end} + 4")
  math(EXPR length "${last} - ${first}")
  string(SUBSTRING "${text}" 0 ${first} text_before)
  string(SUBSTRING "${text}" ${first} ${length} text_block)
  string(SUBSTRING "${text}" ${last} -1 text_after)
  set(${before} "${text_before}" PARENT_SCOPE)
  set(${block} "${text_block}" PARENT_SCOPE)
  set(${after} "${text_after}" PARENT_SCOPE)
endfunction()

function(graft_default_run out copy ours id)
  file(READ ${copy} copy_text)
  file(READ ${ours} our_text)
  split_default_run("${copy_text}" before old_block after)
  split_default_run("${our_text}" unused block unused_too)
  if(old_block STREQUAL "" OR block STREQUAL "")
    message(FATAL_ERROR "no default run (const browser::StageDefaults kStage{ ... };) in ${copy} or ${ours}")
  endif()
  string(REGEX REPLACE "\\.id = \"[a-z0-9_]*\"" ".id = \"${id}\"" block "${block}")
  set(text "${before}${block}${after}")
  if(EXISTS ${out})
    file(READ ${out} old_text)
    if(old_text STREQUAL text)
      return()
    endif()
  endif()
  file(WRITE ${out} "${text}")
endfunction()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
  graft_default_run(${OUT} ${COPY} ${OURS} ${ID})
endif()
