# The CTest test <stage>.build of a workbench stage (cmake/Workbench.cmake): builds its
# program and each of its test programs on its own, so that one that does not compile
# stops none of the others, and notes for each whether it built (<LOG_DIR>/<target>.status,
# 0 when it did) and what the build said (<target>.log). The stage's other tests read
# these notes; "engine" for a status means the stage's engine did not build, so nothing
# else was tried. It passes whatever fails to build: the tests that need it say so.
#   -DBUILD_DIR= -DGENERATOR= -DSTAGE= -DLOG_DIR= -DTARGETS=a,b,c [-DENGINE=<engine library>]
string(REPLACE "," ";" targets "${TARGETS}")
file(MAKE_DIRECTORY ${LOG_DIR})
foreach(target IN LISTS targets ENGINE)
  file(REMOVE ${LOG_DIR}/${target}.status ${LOG_DIR}/${target}.log)
endforeach()
cmake_host_system_information(RESULT jobs QUERY NUMBER_OF_LOGICAL_CORES)

# Builds the targets in ARGN into <log>; <result> is the build's exit status.
function(build result log)
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} -j ${jobs} --target ${ARGN} ${keep_going}
    OUTPUT_FILE ${log} ERROR_FILE ${log} RESULT_VARIABLE status)
  set(${result} ${status} PARENT_SCOPE)
endfunction()

function(note target status log)
  if(NOT log STREQUAL "${LOG_DIR}/${target}.log")
    file(COPY_FILE ${log} ${LOG_DIR}/${target}.log)
  endif()
  file(WRITE ${LOG_DIR}/${target}.status "${status}")
  if(status EQUAL 0)
    message("  built      ${target}")
  else()
    message("  not built  ${target}")
  endif()
endfunction()

message("${STAGE}: building each program on its own (the build's words: ${LOG_DIR}/<target>.log)")
# Without the engine nothing builds: one try, and every target fails with its words.
if(ENGINE)
  build(status ${LOG_DIR}/${ENGINE}.log ${ENGINE})
  if(NOT status EQUAL 0)
    message("  not built  ${ENGINE} (so nothing else is)")
    foreach(target IN LISTS targets)
      note(${target} engine ${LOG_DIR}/${ENGINE}.log)
    endforeach()
    return()
  endif()
endif()

# All of them in one parallel build that keeps going past failures, then each alone:
# a quick no-op for what built, and for what did not, a log of its own errors.
if(GENERATOR MATCHES "Makefiles")
  set(keep_going -- -k)
elseif(GENERATOR MATCHES "Ninja")
  set(keep_going -- -k 0)
endif()
build(status ${LOG_DIR}/all.log ${targets})
if(status EQUAL 0)
  foreach(target IN LISTS targets)
    note(${target} 0 ${LOG_DIR}/all.log)
  endforeach()
  return()
endif()
set(keep_going)
foreach(target IN LISTS targets)
  build(status ${LOG_DIR}/${target}.log ${target})
  note(${target} ${status} ${LOG_DIR}/${target}.log)
endforeach()
