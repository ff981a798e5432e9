# refresh_goldens (cmake -P, run by `cmake --build <build dir> --target refresh_goldens`):
# renders every golden-image case twice, refuses to continue unless the two renders are
# identical (goldens must be deterministic), then replaces tests/render/golden/*.png and the
# README gallery docs/gallery/*.png (each scene as the whole workstation at 1280x800).
# Goldens and gallery images of scenes that no longer exist are removed.
cmake_minimum_required(VERSION 3.25) # script mode: the project's policies
foreach(var ISOPARM COMPARE SCENE_DIR GOLDEN_DIR GALLERY_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "refresh_goldens.cmake: -D${var}=... is missing")
  endif()
endforeach()
include(${CMAKE_CURRENT_LIST_DIR}/render_cases.cmake)

# render(out scene size view): one render, stopping at the first failure.
function(render out scene size view)
  execute_process(COMMAND ${ISOPARM} render ${scene} -o ${out} --size ${size} --view ${view}
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0 OR NOT EXISTS ${out})
    message(FATAL_ERROR "refresh_goldens: `isoparm render ${scene} --size ${size} --view ${view}` failed (${rc})")
  endif()
endfunction()

# render_twice(out scene size view): render, render again, and insist on identical pixels.
function(render_twice out scene size view)
  render(${out} ${scene} ${size} ${view})
  render(${out}.again.png ${scene} ${size} ${view})
  execute_process(COMMAND ${COMPARE} ${out} ${out}.again.png --tolerance 0 --max-fraction 0
                  OUTPUT_QUIET RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "refresh_goldens: two renders of ${scene} (${size}, ${view}) differ: "
                        "the renderer is not deterministic, nothing was replaced for it")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/golden ${WORK_DIR}/gallery ${GOLDEN_DIR} ${GALLERY_DIR})

# Everything is rendered and checked first; the committed files are replaced only at the end.
isoparm_render_cases(${SCENE_DIR} cases)
set(golden_names)
foreach(render_case IN LISTS cases)
  string(REPLACE "|" ";" fields "${render_case}")
  list(GET fields 0 name)
  list(GET fields 1 scene)
  list(GET fields 2 size)
  list(GET fields 3 view)
  message(STATUS "golden  ${name}.png  (${size}, ${view})")
  render_twice(${WORK_DIR}/golden/${name}.png ${scene} ${size} ${view})
  list(APPEND golden_names ${name})
endforeach()

file(GLOB scenes "${SCENE_DIR}/*.json")
list(SORT scenes)
set(gallery_names)
foreach(scene IN LISTS scenes)
  cmake_path(GET scene STEM LAST_ONLY name)
  message(STATUS "gallery ${name}.png  (1280x800, workstation)")
  render_twice(${WORK_DIR}/gallery/${name}.png ${scene} 1280x800 workstation)
  list(APPEND gallery_names ${name})
endforeach()

# install(dir names target): copy the fresh renders over, drop PNGs of vanished scenes.
function(install_renders dir names target)
  file(GLOB old "${target}/*.png")
  foreach(png IN LISTS old)
    cmake_path(GET png STEM LAST_ONLY name)
    if(NOT name IN_LIST names)
      message(STATUS "removing ${png} (no such scene any more)")
      file(REMOVE ${png})
    endif()
  endforeach()
  foreach(name IN LISTS names)
    file(COPY_FILE ${dir}/${name}.png ${target}/${name}.png ONLY_IF_DIFFERENT)
  endforeach()
endfunction()
install_renders(${WORK_DIR}/golden "${golden_names}" ${GOLDEN_DIR})
install_renders(${WORK_DIR}/gallery "${gallery_names}" ${GALLERY_DIR})
list(LENGTH golden_names n_golden)
list(LENGTH gallery_names n_gallery)
message(STATUS "refresh_goldens: ${n_golden} golden images in ${GOLDEN_DIR}, "
               "${n_gallery} gallery images in ${GALLERY_DIR}; look at them before committing")
