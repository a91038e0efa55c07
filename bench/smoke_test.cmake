# ctest's bench.smoke: runs `bench --quick --out OUT` and checks that it wrote what it
# promises. cmake -DPROGRAM=<bench> -DOUT=<folder> -P smoke_test.cmake
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${PROGRAM} --quick --out ${OUT} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "bench --quick exited with ${status}")
endif()
foreach(file results.csv results.md scale.png trajectory.png tunnelling.png
             cost_vs_error_pyramid_10.png cost_vs_error_rain_400.png cost_vs_error_gas.png
             cost_vs_error_slide.png)
  if(NOT EXISTS ${OUT}/${file})
    message(FATAL_ERROR "bench --quick did not write ${file}")
  endif()
endforeach()
