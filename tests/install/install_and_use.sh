#!/usr/bin/env bash
# Installs the build tree into a temporary prefix, checks the layout, builds
# tests/install/ against it with find_package(tagmap) (and pkg-config), then
# simulates a small map with the installed command and detects its tags with
# the external program; and a stock MRPT app reads the installed command's
# CTagMap with the installed plugin.
# Usage: install_and_use.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
build=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" >"$work/install.log"

for f in bin/tagmap lib/tagmap/libtagmap_mrpt_plugin.so lib/cmake/tagmap/tagmapConfig.cmake \
         lib/pkgconfig/tagmap.pc include/tagmap/pipeline.h include/tagmap/maps/CTagMap.h \
         share/tagmap/config/default.yaml share/tagmap/scenes/parking.yaml; do
  [ -e "$prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
echo "installed: $(find "$prefix" -type f | wc -l) files"

# pkg-config sees the package (the build below uses CMake).
if command -v pkg-config >/dev/null; then
  PKG_CONFIG_PATH=$prefix/lib/pkgconfig pkg-config --exists --print-errors tagmap
  echo "pkg-config: tagmap $(PKG_CONFIG_PATH=$prefix/lib/pkgconfig pkg-config --modversion tagmap)"
fi

cmake -S "$src/tests/install" -B "$work/user" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  ${CMAKE_CXX_COMPILER_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER=$CMAKE_CXX_COMPILER_LAUNCHER} >"$work/configure.log"
cmake --build "$work/user" >"$work/build.log" 2>&1 || { tail -30 "$work/build.log"; exit 1; }

"$prefix/bin/tagmap" simulate "$src/tests/reliability/one_tag.yaml" --out "$work/sim" --seed 7 --quiet
"$work/user/detect_tags" "$work/sim/map.pcd" | tee "$work/detect.txt"
grep -q "^tag36h11 3$" "$work/detect.txt"
grep -q "CTagMap registered" "$work/detect.txt"

# The installed plugin, loaded by a stock MRPT app, reads the installed
# command's CTagMap (what the README tells users to do).
if command -v rawlog-edit >/dev/null; then
  "$prefix/bin/tagmap" detect "$work/sim/map.pcd" --quiet --json "$work/tags.json" --tagmap "$work/tags.tagmap"
  rawlog-edit -p "$prefix/lib/tagmap/libtagmap_mrpt_plugin.so" --info -i "$work/tags.tagmap" </dev/null \
    >"$work/rawlog-edit.txt" 2>&1
  grep -Eq "Overall number of objects +: 1$" "$work/rawlog-edit.txt" ||
    { echo "rawlog-edit with the installed plugin cannot read the CTagMap:"; cat "$work/rawlog-edit.txt"; exit 1; }
  echo "rawlog-edit -p <installed plugin> reads the installed command's CTagMap"
fi
