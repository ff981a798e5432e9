# `isoparm render` options: good ones render; each bad one fails with one clear line on stderr
# and writes no PNG (ISOPARM, SCENE, OUT_DIR are given).
file(MAKE_DIRECTORY ${OUT_DIR})
set(out ${OUT_DIR}/options.png)
file(REMOVE ${out})
execute_process(COMMAND ${ISOPARM} render ${SCENE} -o ${out} --view 3d --size 320x200
                  --select 2,2 --indicator 0.3,0.6 --camera 30,40,120 --style wireframe --ids
                  --knot-curves --no-net
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${out})
  message(FATAL_ERROR "render with good options failed (${rc}): ${err}")
endif()

foreach(bad "--select;9,9" "--select;1.5,2" "--indicator;2,0.5" "--indicator;a,b" "--camera;0,95"
            "--camera;10,10,0" "--style;flat" "--size;0x0" "--size;big")
  file(REMOVE ${out})
  execute_process(COMMAND ${ISOPARM} render ${SCENE} -o ${out} ${bad}
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(rc EQUAL 0 OR EXISTS ${out})
    message(FATAL_ERROR "render ${bad} should fail without a PNG (exit ${rc})")
  endif()
  string(STRIP "${err}" err)
  if(err STREQUAL "")
    message(FATAL_ERROR "render ${bad} printed no reason")
  endif()
endforeach()
