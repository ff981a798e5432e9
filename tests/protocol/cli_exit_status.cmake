# The `isoparm geom` command line as outside tests call it: exit statuses, stdout and stderr.
# Run as: cmake -DISOPARM=<binary> -DSOURCE_DIR=<repo> -P cli_exit_status.cmake
if(NOT ISOPARM OR NOT SOURCE_DIR)
  message(FATAL_ERROR "pass -DISOPARM=<path to isoparm> and -DSOURCE_DIR=<repository>")
endif()

set(work "${CMAKE_CURRENT_BINARY_DIR}/cli_exit_status")
file(MAKE_DIRECTORY "${work}")
set(failures 0)

# run_geom(<name> <stdin text or FILE:path> <expected exit>): runs the binary, leaves the
# results in <name>_out, <name>_err, and checks the exit status.
function(run_geom name input expected)
  if(input MATCHES "^FILE:(.*)$")
    execute_process(COMMAND "${ISOPARM}" geom "${CMAKE_MATCH_1}"
                    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  else()
    file(WRITE "${work}/${name}.json" "${input}")
    execute_process(COMMAND "${ISOPARM}" geom INPUT_FILE "${work}/${name}.json"
                    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  endif()
  if(NOT status STREQUAL "${expected}")
    message(SEND_ERROR "${name}: exit status ${status}, expected ${expected}\nstdout: ${out}\nstderr: ${err}")
    math(EXPR failures "${failures} + 1")
    set(failures ${failures} PARENT_SCOPE)
  endif()
  set(${name}_out "${out}" PARENT_SCOPE)
  set(${name}_err "${err}" PARENT_SCOPE)
endfunction()

function(expect name text regex)
  if(NOT text MATCHES "${regex}")
    message(SEND_ERROR "${name}: '${text}' does not match '${regex}'")
  endif()
endfunction()

# A valid request on stdin: exit 0.
run_geom(valid [=[{"op": "evaluate", "curve": {"type": "bezier", "degree": 1, "points": [[0, 0], [2, 2]]}, "params": [0.5]}]=] 0)
expect(valid "${valid_out}" [=[^\{"ok": true, "points": \[\[1\.0, 1\.0, 0\.0\]\]\}
$]=])
expect(valid_stderr "x${valid_err}" "^x$")

# A failing request: exit 1, and the response is still written.
run_geom(failing [=[{"op": "evaluate", "curve": {"type": "bezier", "degree": 1, "points": [[0, 0], [2, 2]]}, "params": [1.5]}]=] 1)
expect(failing "${failing_out}" [=["ok": false, "error": \{"code": "domain", "message": "[^"]+", "path": "/params/0"\}]=])

# Not JSON: exit 2, nothing on stdout, one line with line and column on stderr.
run_geom(not_json "{\"op\": \"evaluate\",\n \"params\": [1,,2]}" 2)
expect(not_json_stdout "x${not_json_out}" "^x$")
expect(not_json_stderr "${not_json_err}" "^[^\n]*line 2, column [0-9]+[^\n]*\n$")
run_geom(empty_input "" 2)
expect(empty_input_stdout "x${empty_input_out}" "^x$")

# A batch with one success and one failure: exit 1, both answered in order.
run_geom(batch [=[[{"op": "basis", "degree": 1, "knots": [0, 0, 1, 1], "param": 0.25}, {"op": "nope"}]]=] 1)
expect(batch "${batch_out}" [=[^\[\{"ok": true, "values": \[0\.75, 0\.25\]\}, \{"ok": false, "error": \{"code": "unknown_op"]=])

# The empty batch: [] and exit 0.
run_geom(empty_batch "[]" 0)
expect(empty_batch "${empty_batch_out}" "^\\[\\]\n$")

# Every example request shipped in assets/requests/ succeeds when given as FILE.
file(GLOB requests "${SOURCE_DIR}/assets/requests/*.json")
list(LENGTH requests count)
if(count LESS 8)
  message(SEND_ERROR "expected the example requests in ${SOURCE_DIR}/assets/requests, found ${count}")
endif()
foreach(request IN LISTS requests)
  get_filename_component(stem "${request}" NAME_WE)
  run_geom(asset_${stem} "FILE:${request}" 0)
  expect(asset_${stem} "${asset_${stem}_out}" "^[[{]")
endforeach()

# A file that does not exist: exit 2 with a message, nothing on stdout.
run_geom(missing_file "FILE:${work}/does-not-exist.json" 2)
expect(missing_file_stdout "x${missing_file_out}" "^x$")

if(failures GREATER 0)
  message(FATAL_ERROR "${failures} exit status check(s) failed")
endif()
