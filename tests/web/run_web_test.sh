#!/usr/bin/env bash
# The web CTest (label web): builds the browser build (app/web/build.sh, into the tree
# `bash .ci/quickstart web` uses, so nothing is built twice), then drives it in headless Chromium
# through puppeteer-core (web_test.js). Skipped, with a message saying what is missing, where
# emscripten, Chromium, node or puppeteer-core is not installed.
#
#   run_web_test.sh SOURCE_DIR WEB_BUILD_DIR ISOPARM COMPARE_PNG OUT_DIR
set -euo pipefail
src=$1 web=$2 isoparm=$3 compare=$4 out=$5

skip() {
  echo "skipped: $*"
  exit 0
}
command -v em++ >/dev/null || skip "emscripten is not installed (apt install emscripten)"
chromium=$(command -v chromium || command -v chromium-browser || true)
[ -n "$chromium" ] || skip "Chromium is not installed (apt install --no-install-recommends chromium)"
command -v node >/dev/null || skip "node is not installed (apt install nodejs)"
modules=$src/tests/web/node_modules
if [ ! -d "$modules/puppeteer-core" ]; then
  command -v npm >/dev/null || skip "puppeteer-core is not installed and there is no npm"
  (cd "$src/tests/web" && npm ci --no-audit --no-fund >&2) ||
    skip "puppeteer-core could not be installed (npm ci in tests/web)"
fi

start=$(date +%s)
bash "$src/app/web/build.sh" "$src" "$web"
echo "web test: the browser build took $(($(date +%s) - start)) s"
rm -rf "$out"
mkdir -p "$out"
NODE_PATH=$modules node "$src/tests/web/web_test.js" --web "$web" --isoparm "$isoparm" \
  --compare "$compare" --assets "$src/assets" --out "$out" --chromium "$chromium" \
  --runs "${ISOPARM_WEB_RUNS:-5}"
