# One golden-image test (cmake -P): render SCENE at SIZE/VIEW into OUT_DIR/NAME.png and compare
# it with GOLDEN; on a mismatch the diff image OUT_DIR/NAME.diff.png is kept and named.
cmake_minimum_required(VERSION 3.25) # script mode: the project's policies
foreach(var ISOPARM COMPARE NAME SCENE SIZE VIEW GOLDEN OUT_DIR TOLERANCE MAX_FRACTION)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "golden_test.cmake: -D${var}=... is missing")
  endif()
endforeach()

file(MAKE_DIRECTORY ${OUT_DIR})
set(out ${OUT_DIR}/${NAME}.png)
set(diff ${OUT_DIR}/${NAME}.diff.png)
file(REMOVE ${out} ${diff})

if(NOT EXISTS ${GOLDEN})
  message(FATAL_ERROR "${NAME}: no golden image ${GOLDEN}; render it with "
                      "`cmake --build <build dir> --target refresh_goldens`, look at it, commit it")
endif()

execute_process(COMMAND ${ISOPARM} render ${SCENE} -o ${out} --size ${SIZE} --view ${VIEW}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT EXISTS ${out})
  message(FATAL_ERROR "${NAME}: `isoparm render ${SCENE} --size ${SIZE} --view ${VIEW}` failed (${rc})")
endif()

execute_process(COMMAND ${COMPARE} ${GOLDEN} ${out} --tolerance ${TOLERANCE}
                        --max-fraction ${MAX_FRACTION} --diff ${diff}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NAME}: the render differs from its golden image\n"
                      "  golden: ${GOLDEN}\n  render: ${out}\n  diff:   ${diff} (differing pixels in red)\n"
                      "If the change is intended: cmake --build <build dir> --target refresh_goldens")
endif()
