#!/usr/bin/env bash
# Runs an MRPT GUI app under a virtual X server, screenshots the whole screen
# after it has had time to load, then closes it. Used by the GUI checks so they
# run headless in CI.
#   gui_screenshot.sh OUT.png LOG SECONDS app args...
# Fails if the app died before the screenshot, logged an error/exception, or
# the screenshot is a flat image (nothing drawn).
set -uo pipefail
png=$1 log=$2 wait_s=$3
shift 3

inner=$(mktemp)
trap 'rm -f "$inner"' EXIT
cat >"$inner" <<'INNER'
png=$1 log=$2 wait_s=$3
shift 3
"$@" </dev/null >"$log" 2>&1 &
app=$!
sleep "$wait_s"
if ! kill -0 "$app" 2>/dev/null; then echo "app exited early:"; cat "$log"; exit 1; fi
import -window root "$png"
kill "$app"; wait "$app" 2>/dev/null
exit 0
INNER
xvfb-run -a -s "-screen 0 1280x1024x24" bash "$inner" "$png" "$log" "$wait_s" "$@" || exit 1

if grep -Eiq "exception|error" "$log"; then
  echo "FAIL: $1 logged an error:"; cat "$log"; exit 1
fi
sd=$(convert "$png" -colorspace Gray -format "%[fx:standard_deviation]" info:)
echo "screenshot $png, grey standard deviation $sd"
awk -v s="$sd" 'BEGIN { exit !(s > 0.02) }' || { echo "FAIL: screenshot looks blank"; exit 1; }
