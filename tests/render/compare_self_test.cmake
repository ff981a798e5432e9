# compare_png's own test (cmake -P): an image matches itself; two different figures of the same
# size do not, and the mismatch leaves a diff image; different sizes do not match either.
cmake_minimum_required(VERSION 3.25) # script mode: the project's policies
foreach(var COMPARE GOLDEN_DIR OUT_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "compare_self_test.cmake: -D${var}=... is missing")
  endif()
endforeach()
file(MAKE_DIRECTORY ${OUT_DIR})
set(a ${GOLDEN_DIR}/fig3a-bspline.png)
set(b ${GOLDEN_DIR}/fig3c-weight-0.3.png)
set(big ${GOLDEN_DIR}/fig3b-weight-5-workstation.png)
set(diff ${OUT_DIR}/self_test.diff.png)
file(REMOVE ${diff})

function(expect status)
  execute_process(COMMAND ${COMPARE} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL status)
    message(FATAL_ERROR "compare_png ${ARGN}: exit ${rc}, expected ${status}\n${out}${err}")
  endif()
endfunction()

expect(0 ${a} ${a} --tolerance 0 --max-fraction 0)
# w22 = 1 against w22 = 0.3: a small change of shape must still be caught at the defaults.
expect(1 ${a} ${b} --diff ${diff})
if(NOT EXISTS ${diff})
  message(FATAL_ERROR "compare_png wrote no diff image ${diff}")
endif()
expect(0 ${a} ${b} --tolerance 255)
expect(1 ${a} ${big})
expect(2 ${a} ${OUT_DIR}/no-such-image.png)
expect(2 ${a})
expect(2 ${a} ${a} --tolerance 300)
