# `isoparm script` as a user meets it (cmake -P): what it writes, what it refuses, its exit
# statuses and messages.
cmake_minimum_required(VERSION 3.25)
foreach(var ISOPARM SCRIPTS OUT_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "script_cli_test.cmake: -D${var}=... is missing")
  endif()
endforeach()
file(REMOVE_RECURSE ${OUT_DIR})
file(MAKE_DIRECTORY ${OUT_DIR})
get_filename_component(SCENES ${SCRIPTS}/../../assets/scenes ABSOLUTE)

# run(NAME EXPECTED_RC MUST_SAY SCRIPT_TEXT [extra args...])
function(run name expected_rc must_say text)
  set(script ${OUT_DIR}/${name}.json)
  file(WRITE ${script} "${text}")
  execute_process(COMMAND ${ISOPARM} script ${script} --out ${OUT_DIR}/${name} ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL expected_rc)
    message(FATAL_ERROR "${name}: exit ${rc}, expected ${expected_rc}\n${out}\n${err}")
  endif()
  string(FIND "${out}${err}" "${must_say}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${name}: the output does not say '${must_say}':\n${out}\n${err}")
  endif()
  set(output "${out}${err}" PARENT_SCOPE)
endfunction()

function(expect_nothing_written name)
  if(EXISTS ${OUT_DIR}/${name})
    file(GLOB written ${OUT_DIR}/${name}/*)
    message(FATAL_ERROR "${name}: wrote ${written} though the script was refused")
  endif()
endfunction()

set(head "{\"format\": \"isoparm-script\", \"version\": 1, \"scene\": \"${SCENES}/fig3a-bspline.json\", \"steps\": [")

# A malformed step anywhere: refused with its path before anything runs or is written.
run(malformed 2 "/steps/2/position/1"
    "${head}{\"screenshot\": \"a.png\", \"size\": [64, 40]},
     {\"command\": \"edit_point\", \"id\": 1, \"i\": 0, \"j\": 0, \"position\": [0, 0, 0]},
     {\"command\": \"edit_point\", \"id\": 1, \"i\": 0, \"j\": 0, \"position\": [0, \"up\", 0]}]}")
expect_nothing_written(malformed)

# A step the document refuses (no control point P9,0): found by the trial run, nothing written.
run(refused 2 "/steps/1/i"
    "${head}{\"screenshot\": \"a.png\", \"size\": [64, 40]},
     {\"command\": \"edit_point\", \"id\": 1, \"i\": 9, \"j\": 0, \"position\": [0, 0, 0]}]}")
expect_nothing_written(refused)
string(FIND "${output}" "nothing was written" at)
if(at EQUAL -1)
  message(FATAL_ERROR "refused: the message does not say that nothing was written:\n${output}")
endif()

# An unknown member of the script, a missing starting scene: refused with the path.
run(unknown_member 2 "unknown member 'step'" "${head}], \"step\": []}")
run(missing_scene 2 "/scene"
    "{\"format\": \"isoparm-script\", \"version\": 1, \"scene\": \"no-such.json\", \"steps\": []}")

# A failed expectation: exit 1, naming the step and both values; the screenshots are written.
run(failed_expect 1 "/steps/2: expected P2,2 of 'hill' at (0, 0, 9), found (0, 0, 2.5)"
    "${head}{\"command\": \"edit_point\", \"id\": 1, \"i\": 2, \"j\": 2, \"position\": [0, 0, 2.5]},
     {\"screenshot\": \"a.png\", \"size\": [64, 40]},
     {\"expect\": {\"id\": 1, \"point\": [2, 2], \"position\": [0, 0, 9]}}]}")
if(NOT EXISTS ${OUT_DIR}/failed_expect/a.png)
  message(FATAL_ERROR "failed_expect: the screenshot was not written")
endif()

# --check: a screenshot like its golden image passes; a different one is exit 1 with a diff
# image; a screenshot without a golden image is named.
set(shot_script "${head}{\"display\": {\"style\": \"shaded\"}}, {\"screenshot\": \"shot.png\", \"view\": \"3d\", \"size\": [96, 60]}]}")
run(golden_source 0 "1 screenshots" "${shot_script}")
run(golden_same 0 "0 differing" "${shot_script}" --check ${OUT_DIR}/golden_source)
set(moved "${head}{\"display\": {\"style\": \"shaded\"}}, {\"command\": \"edit_point\", \"id\": 1, \"i\": 2, \"j\": 2, \"position\": [0, 0, 6]}, {\"screenshot\": \"shot.png\", \"view\": \"3d\", \"size\": [96, 60]}]}")
run(golden_differs 1 "screenshot differs: shot.png" "${moved}" --check ${OUT_DIR}/golden_source)
if(NOT EXISTS ${OUT_DIR}/golden_differs/shot.diff.png)
  message(FATAL_ERROR "golden_differs: no diff image shot.diff.png")
endif()
run(golden_missing 1 "shot.png: cannot open" "${shot_script}" --check ${OUT_DIR}/no-goldens)
# --out and --check the same folder: refused before anything runs (the screenshots would
# replace the golden images and then match them). Named differently, the same folder.
run(golden_self 2 "is the --check folder" "${shot_script}" --check ${OUT_DIR}/golden_self)
execute_process(COMMAND ${ISOPARM} script ${OUT_DIR}/golden_self.json --out ${OUT_DIR}/golden_source
                        --check ${OUT_DIR}/./golden_source/../golden_source
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "is the --check folder")
  message(FATAL_ERROR "golden_self by another name: exit ${rc}\n${err}")
endif()
# A golden image that is a FIFO: named as not a regular file at once (it hung for ever).
file(MAKE_DIRECTORY ${OUT_DIR}/fifo_goldens)
execute_process(COMMAND mkfifo ${OUT_DIR}/fifo_goldens/shot.png)
run(golden_fifo 1 "FIFO" "${shot_script}" --check ${OUT_DIR}/fifo_goldens)

# A screenshot's name is checked byte by byte: a NUL (JSON \u0000) would have written
# .bashrc; separators and hidden names are refused too; nothing is written.
file(MAKE_DIRECTORY ${OUT_DIR}/names)
file(WRITE ${OUT_DIR}/names/.bashrc "keep me\n")
foreach(bad ".bashrc\\u0000.png" "../up.png" "sub\\\\x.png" ".hidden.png" "tab\\t.png" ".png")
  set(text "${head}{\"screenshot\": \"${bad}\", \"size\": [64, 40]}]}")
  file(WRITE ${OUT_DIR}/bad-name.json "${text}")
  execute_process(COMMAND ${ISOPARM} script ${OUT_DIR}/bad-name.json --out ${OUT_DIR}/names
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "/steps/0/screenshot")
    message(FATAL_ERROR "screenshot name ${bad}: exit ${rc}\n${err}")
  endif()
endforeach()
file(READ ${OUT_DIR}/names/.bashrc kept)
file(GLOB named ${OUT_DIR}/names/*)
list(REMOVE_ITEM named ${OUT_DIR}/names/.bashrc)
if(NOT kept STREQUAL "keep me\n" OR named)
  message(FATAL_ERROR "a refused screenshot name wrote something: ${named}")
endif()

# The screenshots' budget, checked before anything runs: one 8192 x 8192 picture (2.9 GB to
# render), or more pictures than the script's total.
run(huge_shot 2 "/steps/0/size" "${head}{\"screenshot\": \"a.png\", \"size\": [8192, 8192]}]}")
expect_nothing_written(huge_shot)
set(many "")
foreach(k RANGE 1 80)
  string(APPEND many "{\"screenshot\": \"s${k}.png\", \"size\": [2048, 2048]}, ")
endforeach()
run(many_shots 2 "/steps/71/screenshot" "${head}${many}{\"pause\": true}]}")
expect_nothing_written(many_shots)
message(STATUS "isoparm script: refusals, expectations and --check behave")
