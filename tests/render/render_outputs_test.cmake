# `isoparm render` never loses a file: the scene as its own output
# (under any name), a directory, a FIFO or a device as output, a file-size limit, a FIFO as
# scene, a NAME_MAX-long output name, and '-' for standard output. ISOPARM, SCENE, OUT_DIR given.
set(dir ${OUT_DIR}/outputs)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir}/sub)
set(scene ${dir}/scene.json)
file(COPY_FILE ${SCENE} ${scene})
file(READ ${scene} original)
set(small --view 3d --size 64x48)

function(expect_refused what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 60)
  if(rc EQUAL 0 OR NOT rc MATCHES "^[0-9]+$")
    message(FATAL_ERROR "${what}: expected exit 1, got '${rc}' (${err})")
  endif()
  string(STRIP "${err}" err)
  if(err STREQUAL "")
    message(FATAL_ERROR "${what}: no reason printed")
  endif()
  message(STATUS "${what}: ${err}")
  set(last_error "${err}" PARENT_SCOPE)
endfunction()

function(expect_scene_intact what)
  file(READ ${scene} now)
  if(NOT now STREQUAL original)
    message(FATAL_ERROR "${what}: the scene was changed")
  endif()
endfunction()

function(expect_no_temporaries where)
  file(GLOB left ${where}/*.tmp-*)
  if(left)
    message(FATAL_ERROR "temporary files left behind: ${left}")
  endif()
endfunction()

# 1. The scene as output, by its own name, through '..', through a link: refused, scene intact.
file(CREATE_LINK scene.json ${dir}/alias.json SYMBOLIC)
foreach(out ${scene} ${dir}/sub/../scene.json ${dir}/alias.json)
  expect_refused("-o ${out}" ${ISOPARM} render ${scene} -o ${out} ${small})
  if(NOT last_error MATCHES "same file")
    message(FATAL_ERROR "-o ${out}: the reason does not say it is the same file: ${last_error}")
  endif()
  expect_scene_intact("-o ${out}")
endforeach()

# 3. Only regular files (or '-'): a directory, a FIFO, a device are refused untouched.
expect_refused("-o a directory" ${ISOPARM} render ${scene} -o ${dir}/sub ${small})
find_program(MKFIFO mkfifo REQUIRED)
execute_process(COMMAND ${MKFIFO} ${dir}/fifo COMMAND_ERROR_IS_FATAL ANY)
expect_refused("-o a FIFO" ${ISOPARM} render ${scene} -o ${dir}/fifo ${small})
expect_refused("-o /dev/null" ${ISOPARM} render ${scene} -o /dev/null ${small})
execute_process(COMMAND test -c /dev/null RESULT_VARIABLE still_device)
if(NOT still_device EQUAL 0)
  message(FATAL_ERROR "/dev/null is no longer a character device")
endif()

# 7. A FIFO as scene: a clean error, never a wait for a writer (TIMEOUT above fails that).
expect_refused("a FIFO as scene" ${ISOPARM} render ${dir}/fifo -o ${dir}/fifo.png ${small})
if(NOT last_error MATCHES "FIFO")
  message(FATAL_ERROR "a FIFO as scene: the reason does not say FIFO: ${last_error}")
endif()

# 2. A file-size limit: exit 1 with a reason, the old PNG untouched, no temporary file.
set(png ${dir}/picture.png)
file(WRITE ${png} "the old picture")
expect_refused("ulimit -f 1" sh -c "ulimit -f 1 && exec \"$0\" render \"$1\" -o \"$2\" --view 3d --size 640x400"
               ${ISOPARM} ${scene} ${png})
if(NOT last_error MATCHES "File too large")
  message(FATAL_ERROR "ulimit -f: the reason does not say the file is too large: ${last_error}")
endif()
file(READ ${png} kept)
if(NOT kept STREQUAL "the old picture")
  message(FATAL_ERROR "ulimit -f: the old PNG was replaced")
endif()
expect_no_temporaries(${dir})

# 2. A name of NAME_MAX (255) bytes: its temporary file must fit too.
string(REPEAT "n" 251 long)
set(long_png ${dir}/${long}.png)
foreach(attempt 1 2)
  execute_process(COMMAND ${ISOPARM} render ${scene} -o ${long_png} ${small}
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS ${long_png})
    message(FATAL_ERROR "a 255-byte output name failed (${rc}): ${err}")
  endif()
endforeach()
expect_no_temporaries(${dir})

# '-' is standard output.
execute_process(COMMAND ${ISOPARM} render ${scene} -o - ${small}
                OUTPUT_FILE ${dir}/stdout.png RESULT_VARIABLE rc ERROR_VARIABLE err)
file(SIZE ${dir}/stdout.png stdout_size)
file(READ ${dir}/stdout.png magic LIMIT 4 HEX)
if(NOT rc EQUAL 0 OR NOT magic STREQUAL "89504e47")
  message(FATAL_ERROR "-o - did not write a PNG to standard output (${rc}, ${magic}): ${err}")
endif()
# 8. A scene that would take gigabytes to show (100 patches at density 256: 16,384 vertices each)
# is refused at once with the work budget's sentence, not rendered for minutes.
set(objects "")
foreach(k RANGE 1 100)
  if(k GREATER 1)
    string(APPEND objects ", ")
  endif()
  string(APPEND objects "{\"id\": ${k}, \"name\": \"p${k}\", \"kind\": \"surface\", \"surface\": "
         "{\"type\": \"bezier\", \"degree\": [1, 1], \"points\": "
         "[[[${k}, 0, 0], [${k}, 1, 0]], [[${k}.5, 0, 0], [${k}.5, 1, 1]]]}}")
endforeach()
file(WRITE ${dir}/big.json "{\"format\": \"isoparm-scene\", \"version\": 1, \"objects\": [${objects}], "
     "\"display\": {\"density\": 256}}")
expect_refused("a scene too large to show" ${ISOPARM} render ${dir}/big.json -o ${dir}/big.png ${small})
if(NOT last_error MATCHES "too large to show" OR EXISTS ${dir}/big.png)
  message(FATAL_ERROR "a scene too large to show: not refused by the work budget: ${last_error}")
endif()

# 6. Under `ulimit -v` too small for the driver and the scene: exit 1 with a reason, never a
# signal from inside the OpenGL driver (it crashes when its malloc fails). Not under the
# sanitizers: AddressSanitizer cannot even start inside such a limit.
set(limits 400000 600000)
if(SANITIZE)
  set(limits "")
endif()
foreach(kib ${limits})
  expect_refused("ulimit -v ${kib}" sh -c "ulimit -v ${kib} && exec \"$0\" render \"$1\" -o \"$2\" --view 3d --size 64x48"
                 ${ISOPARM} ${scene} ${dir}/limited.png)
  if(NOT last_error MATCHES "memory")
    message(FATAL_ERROR "ulimit -v ${kib}: the reason does not say memory: ${last_error}")
  endif()
endforeach()

# 7. -o /dev/stdout is the stream as the shell opened it: `>> log` appends to log (it used to
# replace log with the picture).
file(WRITE ${dir}/log "the first line\n")
execute_process(COMMAND sh -c "exec \"$0\" render \"$1\" -o /dev/stdout --view 3d --size 64x48 >> \"$2\""
                        ${ISOPARM} ${scene} ${dir}/log
                RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 60)
file(READ ${dir}/log log HEX)
if(NOT rc EQUAL 0 OR NOT log MATCHES "^746865206669727374206c696e650a89504e47")
  message(FATAL_ERROR "render -o /dev/stdout >> log did not append the PNG to log (exit ${rc}, ${err})")
endif()
expect_no_temporaries(${dir})

# 8. A --deboor-step too large for an int is checked against the scene like any other.
expect_refused("--deboor-step 99999999999" ${ISOPARM} render ${scene} -o ${dir}/d.png ${small}
               --deboor-step 99999999999)
if(NOT last_error MATCHES "--deboor-step 99999999999 must be 0\\.\\." OR EXISTS ${dir}/d.png)
  message(FATAL_ERROR "--deboor-step 99999999999: ${last_error}")
endif()

expect_scene_intact("the end")
