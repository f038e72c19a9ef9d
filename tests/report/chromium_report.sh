#!/usr/bin/env bash
# Opens a `tagmap detect --report` page in headless Chromium and checks that
# every image on it rendered: the page's inline script writes
# "all N images loaded" into #image-check once each <img> has loaded, and
# Chromium's --dump-dom shows the DOM after that script ran.
#
#   chromium_report.sh TAGMAP FIXTURE SOURCE_DIR ARTIFACTS_DIR
# The map is the simulated parking scene when it exists, else a synthetic
# two-wall map. Kept for people: ARTIFACTS_DIR/report.png (screenshot) and
# ARTIFACTS_DIR/page/ (the report).
set -euo pipefail
tagmap=$1 fixture=$2 src=$3 artifacts=$4

browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "chromium not installed (scripts/install-deps.sh installs it)" >&2
  exit 1
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$artifacts"

# A simulator failure is the simulator tests' business; this test is about
# the page, so it says so and carries on with the synthetic map.
scene=$src/share/scenes/parking.yaml
map=$work/sim/map.pcd
if [ ! -f "$scene" ] || ! "$tagmap" simulate "$scene" --out "$work/sim" >"$work/simulate.log" 2>&1; then
  [ -f "$scene" ] && echo "warning: tagmap simulate $scene failed, using the synthetic map" >&2
  map=$work/map.pcd
  "$fixture" "$map"
fi

"$tagmap" detect "$map" --json "$work/tags.json" --report "$work/report" --quiet
test -s "$work/report/index.html"
images=$(grep -o '<img ' "$work/report/index.html" | wc -l)
if [ "$images" -lt 2 ]; then
  echo "expected the map and at least one candidate image, the page has $images" >&2
  exit 1
fi

# A throw-away profile and no network: the test must not depend on, or
# touch, anything outside its folder.
chrome() {
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --disable-dev-shm-usage --user-data-dir="$work/profile" --virtual-time-budget=10000 "$@" \
    "file://$work/report/index.html" 2>"$work/chromium.log"
}
chrome --dump-dom >"$work/dom.html" || { cat "$work/chromium.log" >&2; exit 1; }
chrome --screenshot="$artifacts/report.png" --window-size=1280,2000 >/dev/null || { cat "$work/chromium.log" >&2; exit 1; }
rm -rf "$artifacts/page" && cp -r "$work/report" "$artifacts/page"  # the page itself, to browse

if ! grep -q "all $images images loaded" "$work/dom.html"; then
  echo "page did not report all $images images loaded; #image-check says:" >&2
  grep -o '<p id="image-check"[^<]*' "$work/dom.html" >&2 || echo "(no #image-check in the DOM)" >&2
  exit 1
fi
test -s "$artifacts/report.png"
echo "all $images images loaded; screenshot: $artifacts/report.png"
