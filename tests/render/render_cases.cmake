# The golden-image cases, shared by the tests (CMakeLists.txt) and refresh_goldens.cmake: every
# scene in assets/scenes as the 3D view alone at 640x400 (small is fast on a CPU rasteriser),
# and a few also as the whole workstation at 1280x800 so that the panels are covered too.
set(ISOPARM_RENDER_WORKSTATION_SCENES curve-designer fig3b-weight-5 fig4-deboor fig6c-split-left-v05
    triangle-cubic)

# Sets out_var to a list of cases "NAME|SCENE|SIZE|VIEW", sorted by scene.
function(isoparm_render_cases scene_dir out_var)
  file(GLOB scenes "${scene_dir}/*.json")
  list(SORT scenes)
  set(cases)
  foreach(scene IN LISTS scenes)
    # LAST_ONLY: "fig3c-weight-0.3.json" is "fig3c-weight-0.3", not "fig3c-weight-0".
    cmake_path(GET scene STEM LAST_ONLY name)
    list(APPEND cases "${name}|${scene}|640x400|3d")
    if(name IN_LIST ISOPARM_RENDER_WORKSTATION_SCENES)
      list(APPEND cases "${name}-workstation|${scene}|1280x800|workstation")
    endif()
  endforeach()
  set(${out_var} "${cases}" PARENT_SCOPE)
endfunction()

# The comparison: a pixel differs when a channel is off by more than the tolerance; a render
# matches when at most this fraction of its pixels differ (anti-aliased edges may move by a
# pixel between llvmpipe builds; a missing net, curve or panel changes far more).
set(ISOPARM_RENDER_TOLERANCE 24)
set(ISOPARM_RENDER_MAX_FRACTION 0.002)
