# The .glb files of `isoparm export` checked by the Khronos glTF validator (the npm package
# gltf-validator, run by node): every gallery scene with a surface, an implicit surface and
# a closed revolution, with no error. The validator is installed once into WORK with npm; where
# node or npm is absent, or the package cannot be installed, the test says so and is skipped.
cmake_minimum_required(VERSION 3.25)
foreach(var ISOPARM SOURCE_DIR WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "gltf_validate.cmake: -D${var}=... is missing")
  endif()
endforeach()
find_program(NODE node)
find_program(NPM npm)
if(NOT NODE OR NOT NPM)
  message("skipped: node and npm are needed to run the Khronos glTF validator")
  return()
endif()
file(MAKE_DIRECTORY ${WORK}/out)
if(NOT EXISTS ${WORK}/node_modules/gltf-validator/package.json)
  execute_process(COMMAND ${NPM} install --no-audit --no-fund --prefix ${WORK}
                          gltf-validator@2.0.0-dev.3.10
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 240)
  if(NOT rc EQUAL 0)
    message("skipped: npm could not install gltf-validator (${rc}):\n${err}")
    return()
  endif()
endif()

set(SCENES ${SOURCE_DIR}/assets/scenes)
set(files)
file(GLOB scenes ${SCENES}/*.json)
foreach(scene IN LISTS scenes)
  cmake_path(GET scene STEM LAST_ONLY name)
  set(args ${scene} -o ${WORK}/out/${name}.glb --samples 24)
  if(name STREQUAL "implicit-gallery")
    list(APPEND args --object sphere)
  endif()
  execute_process(COMMAND ${ISOPARM} export ${args} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(rc EQUAL 0)
    list(APPEND files ${WORK}/out/${name}.glb)
  elseif(NOT err MATCHES "nothing to write")
    message(FATAL_ERROR "isoparm export ${name}.glb: exit ${rc}\n${err}")
  endif()
endforeach()

file(WRITE ${WORK}/validate.js [=[
// Validates each .glb named on the command line; exit 1 if any has an error.
const fs = require('fs');
const validator = require('gltf-validator');
(async () => {
  let failed = false;
  for (const file of process.argv.slice(2)) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)));
    const i = report.issues;
    console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos`);
    for (const m of i.messages)
      if (m.severity <= 1) console.log(`  ${m.severity == 0 ? 'error' : 'warning'} ${m.code} ${m.pointer || ''}: ${m.message}`);
    if (i.numErrors > 0) failed = true;
  }
  process.exit(failed ? 1 : 0);
})().catch((e) => { console.error(e); process.exit(2); });
]=])
list(LENGTH files count)
if(count LESS 10)
  message(FATAL_ERROR "only ${count} .glb files were written")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env NODE_PATH=${WORK}/node_modules ${NODE} ${WORK}/validate.js ${files}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the glTF validator found errors (exit ${rc})")
endif()
