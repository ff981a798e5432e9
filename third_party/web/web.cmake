# The browser build's dependencies (configured with Debian's emscripten:
# `cmake -S . -B build-web -DCMAKE_TOOLCHAIN_FILE=/usr/share/emscripten/cmake/Modules/Platform/Emscripten.cmake`,
# which `bash .ci/quickstart web` does). Included by the top level before anything else when
# EMSCRIPTEN is set; docs/web.md says what differs from the desktop build and why.
#
# - Header-only libraries (GLM, nlohmann-json, stb, tinygltf, CGAL, Boost) are Debian's,
#   reached through a folder of links: never -isystem /usr/include, which would mix glibc's
#   headers into the wasm sysroot's.
# - Dear ImGui is compiled from Debian's source package (fetch_imgui.sh), the same version as
#   the desktop's libimgui-dev, with its GLFW and OpenGL ES 3 backends.
# - GLFW and WebGL 2 are emscripten's own (-sUSE_GLFW=3); no zlib (stb deflates the PNGs), no
#   OpenCASCADE (IGES/STEP import says so), no threads (a static server cannot send the
#   COOP/COEP headers shared memory needs: the worker pool runs on the one thread).

set(ISOPARM_WEB ON)
set(ISOPARM_BENCH OFF CACHE BOOL "" FORCE)
set(ISOPARM_SANITIZE OFF CACHE BOOL "" FORCE)

# Optimised, no debug info in the wasm (it would triple its size). C++ exceptions are used by
# the core (nlohmann's parse errors, std::bad_alloc as a clean error): emscripten 3.1.6's
# prebuilt libraries support them through JavaScript (-fexceptions), not as wasm exceptions.
# SIMD128 runs the tessellation kernel's 2-lane vectors as wasm vectors (every browser
# since 2021).
set(CMAKE_CXX_FLAGS_RELEASE "-O2 -DNDEBUG")
set(CMAKE_CXX_FLAGS_RELWITHDEBINFO "-O2 -DNDEBUG")
add_compile_options(-fexceptions -msimd128)
# What libc++ 13 lacks of C++20 (floating-point to_chars/from_chars, jthread), in every file.
add_compile_options("SHELL:-include ${CMAKE_CURRENT_LIST_DIR}/libcxx_compat.hpp")
add_link_options(-fexceptions)

set(ISOPARM_WEB_INCLUDE ${CMAKE_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${ISOPARM_WEB_INCLUDE})
function(isoparm_web_link name target)
  if(NOT EXISTS ${target})
    message(FATAL_ERROR "the browser build needs ${target} (bash .ci/quickstart web installs it)")
  endif()
  file(CREATE_LINK ${target} ${ISOPARM_WEB_INCLUDE}/${name} SYMBOLIC)
endfunction()
isoparm_web_link(glm /usr/include/glm)
isoparm_web_link(nlohmann /usr/include/nlohmann)
isoparm_web_link(stb /usr/include/stb)
isoparm_web_link(tiny_gltf.h /usr/include/tiny_gltf.h)
isoparm_web_link(CGAL /usr/include/CGAL)
isoparm_web_link(boost /usr/include/boost)

add_library(glm::glm INTERFACE IMPORTED)
target_include_directories(glm::glm SYSTEM INTERFACE ${ISOPARM_WEB_INCLUDE})
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
target_include_directories(nlohmann_json::nlohmann_json SYSTEM INTERFACE ${ISOPARM_WEB_INCLUDE})
# Found by ui/image through this variable (find_path keeps a value already set).
set(ISOPARM_STB_HEADERS ${ISOPARM_WEB_INCLUDE} CACHE PATH "stb's headers (web: the links folder)")
# Trimmed domains' constrained Delaunay triangulation (core/geom/trim/trim_triangulate.cpp):
# Debian's CGAL and Boost headers, header-only, without GMP (the exact fallback is MP_Float
# and Boost.Multiprecision). WebAssembly rounds to nearest only and cannot switch to rounding
# upward, so CGAL's interval filters widen each result to the next double instead
# (CGAL_ALWAYS_ROUND_TO_NEAREST): the predicates stay exact.
add_library(CGAL::CGAL INTERFACE IMPORTED)
target_include_directories(CGAL::CGAL SYSTEM INTERFACE ${ISOPARM_WEB_INCLUDE})
target_compile_definitions(CGAL::CGAL INTERFACE CGAL_ALWAYS_ROUND_TO_NEAREST)
# One thread: Threads::Threads adds nothing (no -pthread, no shared memory).
add_library(Threads::Threads INTERFACE IMPORTED)

# glTF binary export: Debian ships tinygltf as a shared library for the host; the browser
# build compiles its implementation once here (no image loading or writing: the exported
# meshes carry no textures).
add_library(isoparm_tinygltf STATIC ${CMAKE_CURRENT_LIST_DIR}/tinygltf_impl.cpp)
target_include_directories(isoparm_tinygltf SYSTEM PUBLIC ${ISOPARM_WEB_INCLUDE})
target_compile_definitions(isoparm_tinygltf PUBLIC TINYGLTF_NO_STB_IMAGE
                                                   TINYGLTF_NO_STB_IMAGE_WRITE
                                                   TINYGLTF_NO_EXTERNAL_IMAGE)
add_library(TinyGLTF::TinyGLTF ALIAS isoparm_tinygltf)

# Dear ImGui from Debian's source package, fetched once per build tree.
set(ISOPARM_IMGUI_DIR ${CMAKE_BINARY_DIR}/imgui)
if(NOT EXISTS ${ISOPARM_IMGUI_DIR}/src/imgui.cpp)
  message(STATUS "Fetching Dear ImGui's sources (apt-get source imgui) into ${ISOPARM_IMGUI_DIR}")
  execute_process(COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/fetch_imgui.sh ${ISOPARM_IMGUI_DIR}
                  RESULT_VARIABLE fetched OUTPUT_QUIET)
  if(NOT fetched EQUAL 0)
    message(FATAL_ERROR "could not fetch Dear ImGui's sources (third_party/web/fetch_imgui.sh)")
  endif()
endif()
set(imgui ${ISOPARM_IMGUI_DIR}/src)
add_library(isoparm_imgui STATIC
            ${imgui}/imgui.cpp ${imgui}/imgui_draw.cpp ${imgui}/imgui_tables.cpp
            ${imgui}/imgui_widgets.cpp ${imgui}/misc/cpp/imgui_stdlib.cpp
            ${imgui}/backends/imgui_impl_glfw.cpp ${imgui}/backends/imgui_impl_opengl3.cpp)
# The same include layout as Debian's libimgui-dev (<imgui.h>, <imgui_stdlib.h>, backends).
target_include_directories(isoparm_imgui SYSTEM PUBLIC ${imgui} ${imgui}/misc/cpp
                                                       ${imgui}/backends)
target_compile_definitions(isoparm_imgui PUBLIC IMGUI_IMPL_OPENGL_ES3)
target_compile_options(isoparm_imgui PRIVATE -w)
target_link_options(isoparm_imgui INTERFACE -sUSE_GLFW=3 -sMIN_WEBGL_VERSION=2
                    -sMAX_WEBGL_VERSION=2 -sFULL_ES3=1)
