# `isoparm check` as a teacher meets it (cmake -P): exit 0 when all pass, 1 when any fails (an
# unreadable or malformed submission is a failure with its reason), 2 for a bad exercise file
# or a wrong command line; --csv and --json written, never over an input.
cmake_minimum_required(VERSION 3.25)
foreach(var ISOPARM SOURCE_DIR OUT_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_cli.cmake: -D${var}=... is missing")
  endif()
endforeach()
file(REMOVE_RECURSE ${OUT_DIR})
file(MAKE_DIRECTORY ${OUT_DIR})
set(ex ${SOURCE_DIR}/assets/exercises/pull-with-a-weight.json)
set(good ${SOURCE_DIR}/assets/exercises/solutions/pull-with-a-weight.json)

# run(NAME EXPECTED_RC MUST_SAY args...)
function(run name expected_rc must_say)
  execute_process(COMMAND ${ISOPARM} check ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL expected_rc)
    message(FATAL_ERROR "${name}: exit ${rc}, expected ${expected_rc}\n${out}\n${err}")
  endif()
  string(FIND "${out}${err}" "${must_say}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${name}: the output does not say '${must_say}':\n${out}\n${err}")
  endif()
endfunction()

run(all_pass 0 "1 submission: 1 passed, 0 failed" ${ex} ${good})
file(WRITE ${OUT_DIR}/truncated.json "{\"format\": \"isoparm-scene\", \"version\": 1, \"objects\": [")
file(WRITE ${OUT_DIR}/not-a-scene.json "{\"format\": \"isoparm-script\", \"version\": 1, \"steps\": []}")
run(malformed 1 "FAIL  ${OUT_DIR}/truncated.json  (cannot be read): " ${ex} ${good} ${OUT_DIR}/truncated.json)
run(wrong_format 1 "(cannot be read): not an isoparm scene: format must be" ${ex}
    ${OUT_DIR}/not-a-scene.json)
run(missing 1 "no-such.json  (cannot be read)" ${ex} ${OUT_DIR}/no-such.json)
run(summary 1 "3 submissions: 1 passed, 2 failed (2 could not be read)"
    ${ex} ${good} ${OUT_DIR}/truncated.json ${OUT_DIR}/no-such.json)
# A bad exercise file or a wrong command line: exit 2, nothing graded.
file(WRITE ${OUT_DIR}/bad-exercise.json "{\"format\": \"isoparm-exercise\", \"version\": 1, \"task\": \"x\", \"scene\": \"nowhere.json\", \"checks\": [{\"check\": \"degree\", \"degree\": 3}]}")
run(bad_exercise 2 "the starting scene" ${OUT_DIR}/bad-exercise.json ${good})
file(WRITE ${OUT_DIR}/bad-check.json "{\"format\": \"isoparm-exercise\", \"version\": 1, \"task\": \"x\", \"scene\": \"${SOURCE_DIR}/assets/scenes/fig3a-bspline.json\", \"checks\": [{\"check\": \"degree\"}]}")
run(bad_check 2 "(at /checks/0)" ${OUT_DIR}/bad-check.json ${good})
run(no_submission 2 "name at least one submission" ${ex})
run(bad_option 2 "--colour" ${ex} ${good} --colour)
run(output_over_input 2 "" ${ex} ${good} --csv ${good})
# The grades as CSV and JSON.
run(csv_json 1 "2 submissions: 1 passed, 1 failed" ${ex} ${good}
    ${SOURCE_DIR}/tests/exercises/wrong/pull-with-a-weight-b.json
    --csv ${OUT_DIR}/grades.csv --json ${OUT_DIR}/grades.json)
file(STRINGS ${OUT_DIR}/grades.csv rows)
list(LENGTH rows n)
if(NOT n EQUAL 3)
  message(FATAL_ERROR "grades.csv has ${n} rows, expected a header and 2:\n${rows}")
endif()
list(GET rows 2 bad_row)
if(NOT bad_row MATCHES ",fail,3,4,")
  message(FATAL_ERROR "the failed submission's row: ${bad_row}")
endif()
file(READ ${OUT_DIR}/grades.json grades)
string(JSON failed GET "${grades}" summary failed)
if(NOT failed EQUAL 1)
  message(FATAL_ERROR "grades.json says ${failed} failed, expected 1")
endif()
