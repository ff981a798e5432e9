# `isoparm export` as a user meets it (cmake -P): every gallery scene written as STEP, IGES and
# OBJ; meshes of the right size; the refusals (unknown extension, unknown object, a
# non-positive weight, the scene itself as the output, bad --samples), each exit 2 with a
# message that names the offending value, and nothing written (an existing file untouched).
cmake_minimum_required(VERSION 3.25)
foreach(var ISOPARM SOURCE_DIR OUT_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "cli_export.cmake: -D${var}=... is missing")
  endif()
endforeach()
file(REMOVE_RECURSE ${OUT_DIR})
file(MAKE_DIRECTORY ${OUT_DIR})
set(SCENES ${SOURCE_DIR}/assets/scenes)

# run(NAME EXPECTED_RC MUST_SAY args...): `isoparm export args...`.
function(run name expected_rc must_say)
  execute_process(COMMAND ${ISOPARM} export ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL expected_rc)
    message(FATAL_ERROR "${name}: exit ${rc}, expected ${expected_rc}\n${out}\n${err}")
  endif()
  string(FIND "${out}${err}" "${must_say}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${name}: the output does not say '${must_say}':\n${out}\n${err}")
  endif()
endfunction()

function(expect_starts_with file text)
  file(READ ${file} head LIMIT 200)
  string(FIND "${head}" "${text}" at)
  if(NOT at EQUAL 0)
    message(FATAL_ERROR "${file} does not start with '${text}':\n${head}")
  endif()
endfunction()

function(expect_missing file)
  if(EXISTS ${file})
    message(FATAL_ERROR "${file} was written though the export was refused")
  endif()
endfunction()

# Every scene: STEP, IGES and OBJ free-form (the implicit gallery has nothing exact: refused).
file(GLOB scenes ${SCENES}/*.json)
foreach(scene IN LISTS scenes)
  cmake_path(GET scene STEM LAST_ONLY name)
  if(name STREQUAL "implicit-gallery")
    run(${name}_step 2 "an implicit surface has no exact form" ${scene} -o ${OUT_DIR}/${name}.stp)
    expect_missing(${OUT_DIR}/${name}.stp)
    continue()
  endif()
  if(name STREQUAL "triangle-cubic")
    run(${name}_step 2 "have no triangular Bezier patch" ${scene} -o ${OUT_DIR}/${name}.stp)
    expect_missing(${OUT_DIR}/${name}.stp)
    # A mesh of it: 4 points along each edge, 9 triangles, 84 + 50 x 9 bytes of binary STL.
    run(${name}_stl 0 "" ${scene} -o ${OUT_DIR}/${name}.stl --samples 4)
    file(SIZE ${OUT_DIR}/${name}.stl size)
    if(NOT size EQUAL 534)
      message(FATAL_ERROR "${name}.stl is ${size} bytes, not 84 + 50 x 9 = 534")
    endif()
    continue()
  endif()
  run(${name}_step 0 "" ${scene} -o ${OUT_DIR}/${name}.stp)
  expect_starts_with(${OUT_DIR}/${name}.stp "ISO-10303-21;\nHEADER;")
  run(${name}_iges 0 "" ${scene} -o ${OUT_DIR}/${name}.IGES)
  run(${name}_obj 0 "" ${scene} -o ${OUT_DIR}/${name}.obj)
  expect_starts_with(${OUT_DIR}/${name}.obj "# isoparm: exact NURBS geometry (OBJ free-form)")
endforeach()

# Meshes: binary STL is 84 + 50 bytes per triangle (a flat 5 x 5 grid: 32 triangles); the
# curve of the revolution scene is skipped with a note; an implicit surface is polygonized.
run(stl 0 "" ${SCENES}/fig3c-weight-0.3.json -o ${OUT_DIR}/hill.stl --samples 5)
file(SIZE ${OUT_DIR}/hill.stl size)
if(NOT size EQUAL 1684)
  message(FATAL_ERROR "hill.stl: ${size} bytes, expected 84 + 50 x 32 = 1684")
endif()
expect_starts_with(${OUT_DIR}/hill.stl "isoparm binary STL: fig3c-weight-0.3")
run(curve_skipped 0 "skipped 'profile' (id 2): a curve has no mesh"
    ${SCENES}/fig8-revolution.json -o ${OUT_DIR}/vase.ply)
expect_starts_with(${OUT_DIR}/vase.ply "ply\nformat ascii 1.0")
run(obj_mesh 0 "" ${SCENES}/fig8-revolution.json --object vase -o ${OUT_DIR}/vase.obj --mesh)
file(STRINGS ${OUT_DIR}/vase.obj faces REGEX "^f ")
list(LENGTH faces face_count)
if(face_count LESS 100)
  message(FATAL_ERROR "vase.obj: ${face_count} faces")
endif()
run(implicit 0 "" ${SCENES}/implicit-gallery.json --object sphere -o ${OUT_DIR}/sphere.ply)
run(by_id 0 "" ${SCENES}/fig8-revolution.json --object 2 -o ${OUT_DIR}/profile.stp)

# Refusals: exit 2, the offending value named, nothing written, an existing file untouched.
file(WRITE ${OUT_DIR}/old.stp "old")
run(unknown_object 2 "no object has the id or name 'hat'"
    ${SCENES}/fig8-revolution.json --object hat -o ${OUT_DIR}/old.stp)
run(unknown_extension 2 "cannot tell the format of '${OUT_DIR}/x.dwg'"
    ${SCENES}/fig8-revolution.json -o ${OUT_DIR}/x.dwg)
expect_missing(${OUT_DIR}/x.dwg)
run(mesh_with_step 2 "--mesh asks for a mesh" ${SCENES}/fig8-revolution.json -o ${OUT_DIR}/m.stp --mesh)
expect_missing(${OUT_DIR}/m.stp)
run(curve_as_mesh 2 "a curve has no mesh"
    ${SCENES}/fig8-revolution.json --object profile -o ${OUT_DIR}/p.stl)
expect_missing(${OUT_DIR}/p.stl)
run(samples 2 "samples 1 must be 2..1000" ${SCENES}/fig3c-weight-0.3.json -o ${OUT_DIR}/s.stl --samples 1)
expect_missing(${OUT_DIR}/s.stl)
# A number too large for an int is still that rule, not a conversion failure (it was exit 104).
run(samples_huge 2 "samples 99999999999 must be 2..1000" ${SCENES}/fig3c-weight-0.3.json
    -o ${OUT_DIR}/s.stl --samples 99999999999)
expect_missing(${OUT_DIR}/s.stl)
run(samples_not_a_number 2 "--samples" ${SCENES}/fig3c-weight-0.3.json -o ${OUT_DIR}/s.stl
    --samples 1e999)
expect_missing(${OUT_DIR}/s.stl)
# The samples' budget, checked before anything is tessellated: 100 surfaces at 1000 x 1000
# samples are 100 million vertices (about 36 GB as PLY; 25 surfaces took 4.3 GB), refused
# naming the size, the budget and the samples that fit; at 60 x 60 they are written.
set(many_obj "")
foreach(j RANGE 0 8)
  foreach(i RANGE 0 8)
    string(APPEND many_obj "v ${i} ${j} 0\n")
  endforeach()
endforeach()
string(APPEND many_obj "cstype bspline\ndeg 1 1\n")
foreach(k RANGE 1 100)
  string(APPEND many_obj "surf 0 8 0 8")
  foreach(v RANGE 1 81)
    string(APPEND many_obj " ${v}")
  endforeach()
  string(APPEND many_obj "\nparm u 0 0 1 2 3 4 5 6 7 8 8\nparm v 0 0 1 2 3 4 5 6 7 8 8\nend\n")
endforeach()
file(WRITE ${OUT_DIR}/many.obj "${many_obj}")
execute_process(COMMAND ${ISOPARM} import ${OUT_DIR}/many.obj -o ${OUT_DIR}/many.json
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "many.obj did not import: ${rc}\n${err}")
endif()
run(samples_budget 2 "100,000,000 vertices (1000 x 1000 samples of each surface) would take about"
    ${OUT_DIR}/many.json -o ${OUT_DIR}/many.ply --samples 1000)
run(samples_budget_said 2 "samples per direction fit" ${OUT_DIR}/many.json -o ${OUT_DIR}/many.ply
    --samples 1000)
expect_missing(${OUT_DIR}/many.ply)
run(samples_within_budget 0 "" ${OUT_DIR}/many.json -o ${OUT_DIR}/many.ply --samples 60)
run(missing_scene 2 "no-such.json" ${OUT_DIR}/no-such.json -o ${OUT_DIR}/n.stp)
expect_missing(${OUT_DIR}/n.stp)

# A negative weight: IGES and STEP refuse it naming the object and the control point and
# suggesting a mesh; OBJ free-form and the meshes take it.
file(READ ${SCENES}/fig3c-weight-0.3.json scene_text)
string(REPLACE "[1.0, 1.0, 0.3, 1.0, 1.0]" "[1.0, 1.0, -0.3, 1.0, 1.0]" negative "${scene_text}")
if(negative STREQUAL scene_text)
  message(FATAL_ERROR "fig3c-weight-0.3.json no longer has the weight row this test changes")
endif()
file(WRITE ${OUT_DIR}/negative.json "${negative}")
foreach(ext stp igs)
  run(negative_${ext} 2 "'hill' (id 1): weight -0.3 of control point (2, 2) is not positive"
      ${OUT_DIR}/negative.json -o ${OUT_DIR}/old.stp)
endforeach()
file(READ ${OUT_DIR}/old.stp old)
if(NOT old STREQUAL "old")
  message(FATAL_ERROR "old.stp was changed by refused exports: ${old}")
endif()
run(negative_mesh_hint 2 "export a mesh instead (STL, PLY or OBJ mesh)"
    ${OUT_DIR}/negative.json -o ${OUT_DIR}/neg.igs)
expect_missing(${OUT_DIR}/neg.igs)
run(negative_stl 0 "" ${OUT_DIR}/negative.json -o ${OUT_DIR}/neg.stl)
run(negative_obj 0 "" ${OUT_DIR}/negative.json -o ${OUT_DIR}/neg.obj)

# Never over the scene itself, by its name or through a link.
file(COPY_FILE ${SCENES}/fig3a-bspline.json ${OUT_DIR}/scene.stp)
file(READ ${OUT_DIR}/scene.stp before)
run(over_scene 2 "scene.stp" ${OUT_DIR}/scene.stp -o ${OUT_DIR}/scene.stp)
file(CREATE_LINK ${OUT_DIR}/scene.stp ${OUT_DIR}/link.stp SYMBOLIC)
run(over_scene_link 2 "link.stp" ${OUT_DIR}/scene.stp -o ${OUT_DIR}/link.stp)
file(READ ${OUT_DIR}/scene.stp after)
if(NOT before STREQUAL after)
  message(FATAL_ERROR "the scene was overwritten by its own export")
endif()

# No temporary file is left anywhere.
file(GLOB leftovers ${OUT_DIR}/*.tmp-*)
if(leftovers)
  message(FATAL_ERROR "temporary files left: ${leftovers}")
endif()
message(STATUS "isoparm export: all cases passed")
