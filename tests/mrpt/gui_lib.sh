# xdotool helpers for driving MRPT's wxWidgets apps under Xvfb, sourced by
# gui_screenshot.sh inside the virtual display. Xvfb has no window manager:
# windows keep the size the app asked for, focus follows XSetInputFocus only,
# and xdotool's own geometry is off by the parent offset, so geometry comes
# from xwininfo. Every function fails (non-zero) rather than guess.

# gui_wait_window NAME [SECONDS]: prints the id of the first visible window
# whose title contains NAME, waiting for it to appear.
gui_wait_window() {
  local name=$1 t=${2:-60} id
  for ((i = 0; i < t * 4; i++)); do
    id=$(xdotool search --onlyvisible --name "$name" 2>/dev/null | head -1)
    [ -n "$id" ] && { echo "$id"; return 0; }
    sleep 0.25
  done
  echo "no window '$name' after ${t}s" >&2
  return 1
}

# gui_dismiss_tip: closes wxWidgets' "Tip of the Day" (RawLogViewer shows
# one at start-up) with Escape, and checks it went.
gui_dismiss_tip() {
  local tip
  tip=$(gui_wait_window "Tip of the Day" 30) || return 1
  xdotool windowfocus "$tip" key Escape
  sleep 0.5
  ! xdotool search --onlyvisible --name "Tip of the Day" >/dev/null 2>&1
}

# gui_cover_screen WIN: asks for WIN at the top-left corner, screen-sized.
gui_cover_screen() {
  local geom
  geom=$(xdotool getdisplaygeometry)
  xdotool windowmove "$1" 0 0 windowsize "$1" ${geom% *} ${geom#* }
}

# gui_fill_screen WIN: moves WIN to the top-left corner and resizes it to the
# whole screen (a window manager would have maximised it). Repeated until it
# holds: an app still laying out its first frame may resize itself again.
gui_fill_screen() {
  local geom x y w h
  geom=$(xdotool getdisplaygeometry)
  for ((i = 0; i < 20; i++)); do
    gui_cover_screen "$1"
    sleep 1
    read -r x y w h < <(gui_geometry "$1")
    [ "$x $y $w $h" = "0 0 $geom" ] && return 0
  done
  echo "window $1 stays at $x,$y ${w}x$h, not the whole screen $geom" >&2
  return 1
}

# gui_geometry WIN: prints "X Y W H" of WIN on the screen.
gui_geometry() {
  xwininfo -id "$1" | awk '/Absolute upper-left X/ {x=$NF} /Absolute upper-left Y/ {y=$NF}
    /Width:/ {w=$NF} /Height:/ {h=$NF} END {print x, y, w, h}'
}

# gui_gl_canvas WIN: prints the id of the largest child X window of WIN.
# wxGTK gives every GL canvas its own X window (ordinary widgets have none),
# so that is the 3D view.
gui_gl_canvas() {
  local best="" area=0 id w h
  for id in $(xwininfo -children -id "$1" | awk '/^ +0x/ {print $1}'); do
    read -r _ _ w h < <(gui_geometry "$id")
    if ((w * h > area)); then area=$((w * h)) best=$id; fi
  done
  [ -n "$best" ] && echo "$best"
}

# gui_big_canvas WIN: prints the id of WIN's GL canvas once it covers at
# least a quarter of the screen. An app may shrink its window again after
# gui_fill_screen (SceneViewer3D did once, while loading a large scene), so
# the window is filled again each second until its canvas is big.
gui_big_canvas() {
  local geom view w h
  geom=$(xdotool getdisplaygeometry)
  for ((i = 0; i < 20; i++)); do
    view=$(gui_gl_canvas "$1") && read -r _ _ w h < <(gui_geometry "$view") &&
      ((4 * w * h >= ${geom% *} * ${geom#* })) && { echo "$view"; return 0; }
    gui_cover_screen "$1"
    sleep 1
  done
  echo "the 3D view of window $1 stays small (${w:-0}x${h:-0})" >&2
  return 1
}

# gui_orbit WIN DX DY: drags with the left button from the centre of WIN by
# DX, DY pixels in small steps, as a hand would. MRPT's canvases turn the
# camera by 0.2 deg per pixel: azimuth -= 0.2*DX, elevation += 0.2*DY.
gui_orbit() {
  local x y w h n=20
  read -r x y w h < <(gui_geometry "$1")
  local cx=$((x + w / 2)) cy=$((y + h / 2))
  xdotool mousemove $cx $cy mousedown 1
  for ((i = 1; i <= n; i++)); do
    xdotool mousemove $((cx + $2 * i / n)) $((cy + $3 * i / n))
    sleep 0.05
  done
  xdotool mouseup 1
  sleep 0.5
}

# gui_zoom WIN CLICKS: mouse wheel over WIN, towards the camera's target
# (CLICKS > 0) or away from it.
gui_zoom() {
  local x y w h button=4 n=$2
  read -r x y w h < <(gui_geometry "$1")
  ((n < 0)) && button=5 n=$((-n))
  xdotool mousemove $((x + w / 2)) $((y + h / 2))
  for ((i = 0; i < n; i++)); do xdotool click $button; sleep 0.05; done
  sleep 0.5
}

# gui_rawlog_select MAIN ENTRY: selects rawlog entry ENTRY (0 = the first)
# in RawLogViewer's tree and waits for the 3D view it opens. The tree has no
# X window of its own: its root row sits right under the toolbar, at the same
# place in every run; a click there focuses the tree, then Down moves the
# selection one row (CRawlogTreeView rows are 17 px, keys handled in OnKey).
gui_rawlog_select() {
  local before after
  before=$(xwininfo -children -id "$1" | grep -c '^ *0x')
  # Retried: until the file has loaded the tree has no rows to select. Each
  # try starts again from the root row, so it lands on the same entry.
  for ((try = 0; try < 8; try++)); do
    xdotool mousemove 60 105 click 1
    sleep 0.3
    xdotool key --repeat $(($2 + 1)) --delay 100 Down
    for ((i = 0; i < 20; i++)); do
      after=$(xwininfo -children -id "$1" | grep -c '^ *0x')
      ((after > before)) && { sleep 1; return 0; }
      sleep 0.25
    done
  done
  echo "RawLogViewer opened no 3D view for entry $2" >&2
  return 1
}

# The two apps' ways to a 3D view with the tags; each sets `view` to the GL
# canvas for gui_screenshot.sh to check.
#   gui_rawlogviewer_3d ENTRY ORBIT_DX ORBIT_DY ZOOM_CLICKS
# RawLogViewer's 3D view always starts from its own camera around the origin
# (it overrides the scene's), so the test turns and zooms it like a user.
gui_rawlogviewer_3d() {
  local main
  main=$(gui_wait_window "RawlogViewer - Part") && gui_dismiss_tip && gui_fill_screen "$main" &&
    gui_rawlog_select "$main" "$1" && view=$(gui_big_canvas "$main") &&
    gui_orbit "$view" "$2" "$3" && gui_zoom "$view" "$4"
}
# SceneViewer3D starts from the camera stored in the .3Dscene.
gui_sceneviewer_3d() {
  local main
  main=$(gui_wait_window "SceneViewer3D - Part") && gui_fill_screen "$main" && view=$(gui_big_canvas "$main")
}
