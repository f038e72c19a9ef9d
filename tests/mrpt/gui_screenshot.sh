#!/usr/bin/env bash
# Runs an MRPT GUI app under a virtual X server, drives it to its 3D view with
# xdotool (ACTIONS: gui_lib.sh calls that set `view` to the GL canvas),
# screenshots the whole screen, then closes it. Used by the GUI checks so
# they run headless in CI.
#   gui_screenshot.sh OUT.png LOG "ACTIONS" app args...
# Writes OUT.png (the screen) and OUT_3d.png (the 3D view alone). Fails if
# the app died, logged an error/exception, the actions failed, the screen is
# flat (nothing drawn), or the 3D view shows no tag: tag patterns are the
# only white in it (points are jet-coloured, labels magenta, background grey).
set -uo pipefail
png=$1 log=$2 actions=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
view_png=${png%.png}_3d.png
min_tag_pixels=${GUI_MIN_TAG_PIXELS:-50}

inner=$(mktemp) home=$(mktemp -d)
trap 'rm -rf "$inner" "$home"' EXIT
cat >"$inner" <<'INNER'
png=$1 log=$2 actions=$3 lib=$4
shift 4
source "$lib"
"$@" </dev/null >"$log" 2>&1 &
app=$!
view=""
eval "$actions" || { echo "FAIL: GUI actions: $actions"; import -window root "$png"; kill "$app"; exit 1; }
sleep 2  # let the last camera move render
if ! kill -0 "$app" 2>/dev/null; then echo "app exited early:"; cat "$log"; exit 1; fi
import -window root "$png"
gui_geometry "$view" >"$png.view"
kill "$app"; wait "$app" 2>/dev/null
exit 0
INNER
# A fresh HOME: the apps keep settings and GTK its recent-files list there.
HOME=$home xvfb-run -a -s "-screen 0 1600x1200x24" bash "$inner" "$png" "$log" "$actions" "$here/gui_lib.sh" "$@" ||
  exit 1

if grep -Eiq "exception|error" "$log"; then
  echo "FAIL: $1 logged an error:"; cat "$log"; exit 1
fi
sd=$(convert "$png" -colorspace Gray -format "%[fx:standard_deviation]" info:)
echo "screenshot $png, grey standard deviation $sd"
awk -v s="$sd" 'BEGIN { exit !(s > 0.02) }' || { echo "FAIL: screenshot looks blank"; exit 1; }

read -r x y w h <"$png.view" && rm -f "$png.view"
convert "$png" -crop "${w}x${h}+${x}+${y}" +repage "$view_png"
white=$(convert "$view_png" -colorspace Gray -threshold 96% -format "%[fx:round(mean*w*h)]" info:)
echo "3D view $view_png (${w}x${h}): $white white pixels of tag patterns"
((white >= min_tag_pixels)) || { echo "FAIL: no tag visible in the 3D view (< $min_tag_pixels white pixels)"; exit 1; }
