#!/usr/bin/env bash
# The libraries `isoparm` maps when it starts (the dynamic loader's list, as ldd prints it)
# must not include FFmpeg's: they are the video module's (ui/figure/video_codec.hpp), loaded by
# the first animation. Linked into the program they cost every process about 80 ms of start-up.
# Usage: start_up_libraries.sh ISOPARM
set -euo pipefail
isoparm=$1
libs=$(LD_TRACE_LOADED_OBJECTS=1 "$isoparm")
count=$(grep -c '=>' <<<"$libs" || true)
echo "start-up: isoparm maps $count shared libraries"
if grep -E 'lib(avcodec|avformat|avfilter|swscale)\.so' <<<"$libs"; then
  echo "start-up: FFmpeg is linked into the program (above); it belongs in libisoparm_video.so" >&2
  exit 1
fi
