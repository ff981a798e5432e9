# A typical wrong answer: `isoparm check` grades it as failing (exit 1) and says why, with the
# message the exercise's first failing check gives for it (MESSAGE, a regular expression).
cmake_minimum_required(VERSION 3.25)
execute_process(COMMAND ${ISOPARM} check ${EXERCISE} ${SUBMISSION}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "exit ${rc}, expected 1 (a failed submission):\n${out}\n${err}")
endif()
if(NOT out MATCHES "FAIL  [^\n]*${MESSAGE}")
  message(FATAL_ERROR "the grade does not say '${MESSAGE}':\n${out}\n${err}")
endif()
if(NOT out MATCHES "1 submission: 0 passed, 1 failed")
  message(FATAL_ERROR "no summary line:\n${out}")
endif()
