#!/usr/bin/env bash
# The Debian package as a user gets it: cpack builds isoparm_VERSION_ARCH.deb from this build
# tree, dpkg-deb unpacks it into an empty root, and the unpacked program runs from there on an
# unpacked scene, finding its own files beside itself (not in the source or build tree).
# Usage: package_test.sh BUILD_DIR VERSION
set -euo pipefail
build=$1
version=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "package: $*" >&2; exit 1; }

cpack --config "$build/CPackConfig.cmake" -B "$work/out" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log" >&2; fail "cpack failed"; }
deb=$(ls "$work"/out/isoparm_"$version"_*.deb 2>/dev/null | head -n 1)
[ -n "$deb" ] || fail "no isoparm_${version}_*.deb in $(ls "$work/out")"
echo "package: built $(basename "$deb") ($(du -k "$deb" | cut -f1) KiB)"

depends=$(dpkg-deb -f "$deb" Depends)
echo "package: Depends: $depends"
for need in libc6 libglfw3 fonts-dejavu-core libgl1-mesa-dri; do
  grep -q "$need" <<<"$depends" || fail "Depends lacks $need"
done

root=$work/root
dpkg-deb -x "$deb" "$root"
for f in usr/bin/isoparm usr/share/man/man1/isoparm.1.gz usr/share/applications/isoparm.desktop \
         usr/share/icons/hicolor/256x256/apps/isoparm.png usr/share/isoparm/scenes/fig8-revolution.json \
         usr/share/doc/isoparm/README.md usr/lib/isoparm/libisoparm_video.so; do
  [ -e "$root/$f" ] || fail "the package lacks /$f"
done

bin=$root/usr/bin/isoparm
[ "$("$bin" --version)" = "isoparm $version" ] || fail "--version says '$("$bin" --version)'"
# The unpacked program finds the scenes unpacked beside it, wherever its prefix is.
first=$("$bin" examples | head -n 1)
case "$first" in
  "$root"/usr/share/isoparm/scenes/*.json) ;;
  *) fail "isoparm examples lists '$first', not a scene under the unpacked prefix" ;;
esac
"$bin" render "$root/usr/share/isoparm/scenes/fig8-revolution.json" --size 320x200 -o "$work/x.png"
[ -s "$work/x.png" ] || fail "render wrote no picture"
echo "package: the unpacked isoparm renders an unpacked scene"
# Its video module, unpacked beside it (PREFIX/lib/isoparm), makes an animation.
"$bin" animate "$root/usr/share/isoparm/scenes/fig4-deboor.json" --deboor --size 160x100 \
  -o "$work/x.gif" >/dev/null || fail "animate failed"
[ -s "$work/x.gif" ] || fail "animate wrote no GIF"
echo "package: the unpacked isoparm animates through its unpacked video module"
echo '{"op":"basis","degree":2,"knots":[0,0,0,1,1,1],"param":0.5}' | "$bin" geom >/dev/null ||
  fail "isoparm geom failed"
echo "1 passed, 0 failed"
