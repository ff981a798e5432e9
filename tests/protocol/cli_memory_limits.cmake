# Out of memory is an error, never a signal: `isoparm geom` on every request
# in assets/requests plus heavy ones, `isoparm export` and `import`, and (with the GUI)
# `isoparm script` and `render` on scenes, each under several `ulimit -v` caps. Before the fix 23 of 112 such geom runs and 10 of 28 render runs
# ended in SIGABRT or SIGSEGV. Exit statuses must be numbers 0..2; a signal is not.
# Run as: cmake -DISOPARM=<binary> -DSOURCE_DIR=<repo> -DWORK=<dir> -DRENDER=ON|OFF -P ...
if(SANITIZE)
  message(STATUS "skipped: AddressSanitizer cannot start inside an address-space limit")
  return()
endif()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(bicubic "{\"type\": \"bezier\", \"degree\": [3, 3], \"points\": [[[0,0,0],[0,1,0],[0,2,0],[0,3,0]], [[1,0,0],[1,1,1],[1,2,1],[1,3,0]], [[2,0,0],[2,1,1],[2,2,1],[2,3,0]], [[3,0,0],[3,1,0],[3,2,0],[3,3,0]]]}")
file(WRITE ${WORK}/tessellate.json "{\"op\": \"tessellate\", \"surface\": ${bicubic}, \"samples\": [1000, 1000]}")
file(WRITE ${WORK}/batch.json "[{\"op\": \"tessellate\", \"surface\": ${bicubic}, \"samples\": [1000, 1000]}, {\"op\": \"basis\", \"degree\": 1, \"knots\": [0, 0, 1, 1], \"param\": 0.5}]")
set(params "[0.0, 0.0]")
foreach(k RANGE 1 20000)
  string(APPEND params ", [0.5, 0.25]")
endforeach()
file(WRITE ${WORK}/evaluate.json "{\"op\": \"evaluate\", \"surface\": ${bicubic}, \"derivatives\": 3, \"normals\": true, \"params\": [${params}]}")
file(GLOB requests ${SOURCE_DIR}/assets/requests/*.json)
list(APPEND requests ${WORK}/tessellate.json ${WORK}/batch.json ${WORK}/evaluate.json)

set(signals 0)
set(runs 0)
function(run_limited kib)
  execute_process(COMMAND sh -c "ulimit -v ${kib} && exec \"$0\" \"$@\"" ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err TIMEOUT 120)
  math(EXPR runs "${runs} + 1")
  set(runs ${runs} PARENT_SCOPE)
  if(NOT rc MATCHES "^[0-2]$")
    message(SEND_ERROR "ulimit -v ${kib}: ${ARGN}: ended with '${rc}'\n${err}")
    math(EXPR signals "${signals} + 1")
    set(signals ${signals} PARENT_SCOPE)
  endif()
endfunction()

# The caps start above what the loader needs to map the program and its shared libraries
# (OpenCASCADE's data exchange, for `isoparm import`, alone maps tens of megabytes): below that
# the loader itself refuses to start the program (status 127) before any of our code runs.
set(base 0)
foreach(kib RANGE 20000 400000 10000)
  execute_process(COMMAND sh -c "ulimit -v ${kib} && exec \"$0\" --version" ${ISOPARM}
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET TIMEOUT 60)
  if(rc EQUAL 0)
    set(base ${kib})
    break()
  endif()
endforeach()
if(base EQUAL 0)
  message(FATAL_ERROR "isoparm --version did not start under any cap up to 400000 KiB")
endif()
message(STATUS "the program starts from ulimit -v ${base} KiB")
foreach(request ${requests})
  foreach(extra 0 30000 120000 270000)
    math(EXPR kib "${base} + ${extra}")
    run_limited(${kib} ${ISOPARM} geom ${request})
  endforeach()
endforeach()

# Export and import end with an error, never a signal, under the same caps: every format out
# (the meshes at 300 x 300 samples), IGES, STEP and OBJ back in (IGES and STEP through the
# OpenCASCADE reader's child process, which inherits the cap). Before the fix export aborted
# with bad_alloc in 10 of 30 capped runs.
set(vase ${SOURCE_DIR}/assets/scenes/fig8-revolution.json)
foreach(ext stp igs obj stl ply glb)
  execute_process(COMMAND ${ISOPARM} export ${vase} -o ${WORK}/vase.${ext} --samples 300
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  foreach(extra 0 30000 120000 270000)
    math(EXPR kib "${base} + ${extra}")
    run_limited(${kib} ${ISOPARM} export ${vase} -o ${WORK}/capped.${ext} --samples 300)
  endforeach()
endforeach()
foreach(ext stp igs obj)
  foreach(extra 0 30000 120000 270000)
    math(EXPR kib "${base} + ${extra}")
    run_limited(${kib} ${ISOPARM} import ${WORK}/vase.${ext} -o ${WORK}/capped-${ext}.json)
  endforeach()
endforeach()

# (A 160 MB OBJ under 1 GiB: tests/exchange/cli_import_large_obj.cmake.)

if(RENDER)
  # `isoparm script` (its trial run, then EGL for the screenshots) under the render caps.
  foreach(extra 70000 270000 570000 870000)
    math(EXPR kib "${base} + ${extra}")
    run_limited(${kib} ${ISOPARM} script ${SOURCE_DIR}/tests/scripts/deboor-steps.json
                --out ${WORK}/script-shots)
  endforeach()
  foreach(scene ${SOURCE_DIR}/assets/scenes/fig3a-bspline.json ${SOURCE_DIR}/assets/scenes/fig9-skinned.json)
    foreach(extra 70000 270000 570000 770000 870000)
      math(EXPR kib "${base} + ${extra}")
      run_limited(${kib} ${ISOPARM} render ${scene} -o ${WORK}/out.png --view 3d --size 160x100)
    endforeach()
  endforeach()
endif()
message(STATUS "${runs} runs under ulimit -v, ${signals} ended by a signal")
