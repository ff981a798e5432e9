# `isoparm geom FILE` and standard input never block, abort or grow without end:
# a directory, /proc/self/mem, a device, a FIFO, and input above the 256 MiB
# cap. Run as: cmake -DISOPARM=<binary> -DWORK=<scratch directory> -P cli_inputs.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/dir)
find_program(MKFIFO mkfifo REQUIRED)
execute_process(COMMAND ${MKFIFO} ${WORK}/fifo COMMAND_ERROR_IS_FATAL ANY)

# A file that is not a regular file: exit 2, one line naming it, nothing on stdout. A TIMEOUT
# turns a blocked open into a failure; a signal (the old SIGABRT) is not a number.
foreach(input ${WORK}/dir /proc/self/mem /dev/zero ${WORK}/fifo)
  execute_process(COMMAND ${ISOPARM} geom ${input} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err TIMEOUT 60)
  if(NOT rc STREQUAL "2" OR NOT out STREQUAL "" OR NOT err MATCHES "isoparm geom: cannot")
    message(FATAL_ERROR "geom ${input}: expected exit 2 and one reason, got '${rc}'\n${out}\n${err}")
  endif()
  message(STATUS "geom ${input}: ${err}")
endforeach()

# Standard input without end: refused at 256 MiB with a `limit` response, exit 1.
execute_process(COMMAND ${ISOPARM} geom INPUT_FILE /dev/zero RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
if(NOT rc STREQUAL "1" OR NOT out MATCHES "\"code\": *\"limit\"" OR NOT out MATCHES "256 MiB")
  message(FATAL_ERROR "geom < /dev/zero: expected a limit response and exit 1, got '${rc}'\n${out}\n${err}")
endif()
message(STATUS "geom < /dev/zero: ${out}")
