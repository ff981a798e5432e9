#!/usr/bin/env bash
# Dear ImGui's sources for the browser build, from Debian's source package (the binary
# libimgui-dev ships a compiled library and headers, no .cpp files). Fetched at configure time
# through a private apt configuration under DEST, so the system's apt settings stay untouched
# and nothing is ever committed:
#
#   bash third_party/web/fetch_imgui.sh DEST
#
# leaves the unpacked sources in DEST/src (imgui.cpp, imgui_*.cpp, backends/) and prints that
# path. The version is the installed libimgui-dev's, so the desktop and browser builds run the
# same ImGui (bookworm: 1.86); without it, the archive's current one. A second run with the
# sources in place does nothing.
set -euo pipefail

dest=${1:?usage: fetch_imgui.sh DEST}
mkdir -p "$dest"
dest=$(cd "$dest" && pwd)
if [ -f "$dest/src/imgui.cpp" ] && [ -f "$dest/src/backends/imgui_impl_opengl3.cpp" ]; then
  echo "$dest/src"
  exit 0
fi

say() { echo "fetch_imgui: $*" >&2; }
for tool in apt-get dpkg-source; do
  command -v "$tool" >/dev/null || { say "needs $tool (apt install dpkg-dev)"; exit 1; }
done

# The deb-src line points at the same archive the system's own sources use.
uri=http://deb.debian.org/debian
suite=bookworm
for f in /etc/apt/sources.list.d/debian.sources /etc/apt/sources.list; do
  [ -f "$f" ] || continue
  u=$(grep -m1 -oE '(URIs:|^deb) +[a-z]+://[^ ]+' "$f" | grep -oE '[a-z]+://[^ ]+' || true)
  s=$(grep -m1 -oE '^Suites: +[a-z]+' "$f" | awk '{print $2}' || true)
  [ -z "$s" ] && s=$(grep -m1 -E '^deb ' "$f" | awk '{print $3}' || true)
  [ -n "$u" ] && uri=$u
  [ -n "$s" ] && suite=$s
  break
done

apt_dir=$dest/apt
rm -rf "$apt_dir"
mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$apt_dir/preferences.d"
keyring=/usr/share/keyrings/debian-archive-keyring.gpg
signed=""
[ -f "$keyring" ] && signed="[signed-by=$keyring] "
echo "deb-src ${signed}$uri $suite main" >"$apt_dir/sources.list"
: >"$apt_dir/status"
cat >"$apt_dir/apt.conf" <<EOF
Dir::Etc::sourcelist "$apt_dir/sources.list";
Dir::Etc::sourceparts "/nonexistent";
Dir::Etc::preferencesparts "$apt_dir/preferences.d";
Dir::State::Lists "$apt_dir/lists";
Dir::State::status "$apt_dir/status";
Dir::Cache "$apt_dir/cache";
Dir::Cache::pkgcache "";
Dir::Cache::srcpkgcache "";
APT::Sandbox::User "root";
EOF
export APT_CONFIG=$apt_dir/apt.conf

version=$(dpkg-query -W -f='${Version}' libimgui-dev 2>/dev/null || true)
version=${version%+b[0-9]*} # a binary-only rebuild (+b1) has its source's version
say "apt-get source imgui${version:+=$version} from $uri $suite"
apt-get update -qq >&2
rm -rf "$dest/unpack"
mkdir -p "$dest/unpack"
(cd "$dest/unpack" && apt-get source -qq "imgui${version:+=$version}" >&2)
unpacked=$(find "$dest/unpack" -mindepth 1 -maxdepth 1 -type d -name 'imgui-*' | head -n 1)
[ -n "$unpacked" ] && [ -f "$unpacked/imgui.cpp" ] || { say "no imgui sources unpacked"; exit 1; }
rm -rf "$dest/src"
mv "$unpacked" "$dest/src"
rm -rf "$dest/unpack" "$apt_dir/lists" "$apt_dir/cache"
echo "$dest/src"
