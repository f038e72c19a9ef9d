#!/usr/bin/env bash
# Installs every build and test dependency of tagmap from Debian packages.
# Idempotent: re-running it when everything is present is quick and harmless.
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config
  libmrpt-dev mrpt-apps
  libeigen3-dev
  libopencv-dev libopencv-contrib-dev
  libapriltag-dev
  liboctomap-dev
  libgtest-dev googletest
  xvfb xauth imagemagick
  xdotool x11-utils        # tests/mrpt: drive RawLogViewer / SceneViewer3D to their 3D views (xwininfo)
  chromium                 # tests/report: the HTML report opened in a headless browser
  clang libclang-rt-14-dev
)

missing=()
for p in "${PACKAGES[@]}"; do
  [[ $(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true) == *"install ok installed"* ]] || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages already installed"
  exit 0
fi

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" </dev/null
