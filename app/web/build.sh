#!/usr/bin/env bash
# Configures and builds the browser build with Debian's emscripten:
#
#   bash app/web/build.sh SOURCE_DIR BUILD_DIR [JOBS]
#
# leaves BUILD_DIR/index.html (the workstation), isoparm-geom.js (the geometry alone) and
# geom-example.html; serve BUILD_DIR with any static server (docs/web.md). Used by
# `bash .ci/quickstart web` and by the web CTest (tests/web), which share the one build tree.
# em++ goes through ccache when it is installed (CCACHE_BASEDIR as the caller set it).
set -euo pipefail
src=$(cd "${1:?usage: build.sh SOURCE_DIR BUILD_DIR [JOBS]}" && pwd)
dir=${2:?usage: build.sh SOURCE_DIR BUILD_DIR [JOBS]}
jobs=${3:-$(nproc 2>/dev/null || echo 2)}

toolchain=/usr/share/emscripten/cmake/Modules/Platform/Emscripten.cmake
if ! command -v em++ >/dev/null || [ ! -f "$toolchain" ]; then
  echo "build.sh: needs Debian's emscripten (apt install emscripten)" >&2
  exit 1
fi
# emcc runs its JavaScript tools with node, which looks for Debian's node modules (acorn) here
# only when node itself is Debian's.
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$src" -B "$dir" -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DCMAKE_BUILD_TYPE=Release \
  "${launcher[@]}" >/dev/null
cmake --build "$dir" -j"$jobs"
