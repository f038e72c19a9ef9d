#!/usr/bin/env bash
# Malformed point-cloud maps given to `tagmap detect`: each must be rejected
# with one line naming the file and the place, and leave outputs alone.
# Points that are merely unusable (NaN/Inf, absurdly far) are skipped and
# counted instead, and an empty map is a valid, empty result.
source "$(dirname "$0")/lib.sh"
M=$WORK/maps
mkdir -p "$M"

# pcd_header FIELDS SIZES TYPES WIDTH POINTS DATA: a PCD v0.7 header.
pcd_header() {
	printf 'VERSION 0.7\nFIELDS %s\nSIZE %s\nTYPE %s\nCOUNT %s\nWIDTH %s\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS %s\nDATA %s\n' \
		"$1" "$2" "$3" "$(sed 's/[^ ]\+/1/g' <<<"$1")" "$4" "$5" "$6"
}
# floats N: N little-endian float32 x y z intensity records, on a small grid.
floats() { perl -e 'print pack("f<*", map { ($_ % 7) * 0.1, int($_ / 7) * 0.1, 1.0, $_ % 2 } 0 .. $ARGV[0] - 1)' "$1"; }

# ---- PCD ------------------------------------------------------------------
CASE=pcd-truncated-binary
{ pcd_header "x y z intensity" "4 4 4 4" "F F F F" 100 100 binary; floats 50; } >"$M/cut.pcd"
expect_detect_rejects "$M/cut.pcd" "cut\.pcd: byte offset [0-9]+: truncated"

CASE=pcd-truncated-ascii
{ pcd_header "x y z intensity" "4 4 4 4" "F F F F" 5 5 ascii; printf '0 0 1 5\n0.1 0 1 6\n'; } >"$M/cut_ascii.pcd"
expect_detect_rejects "$M/cut_ascii.pcd" "cut_ascii\.pcd: line [0-9]+: file ends after 2 of 5 points"

CASE=pcd-cut-in-header
pcd_header "x y z intensity" "4 4 4 4" "F F F F" 5 5 ascii | head -4 >"$M/cut_header.pcd"
expect_detect_rejects "$M/cut_header.pcd" "cut_header\.pcd: header: no DATA line"

CASE=pcd-points-vs-width
pcd_header "x y z intensity" "4 4 4 4" "F F F F" 5 10 ascii >"$M/mismatch.pcd"
expect_detect_rejects "$M/mismatch.pcd" "mismatch\.pcd: header: POINTS 10 does not match WIDTH"

CASE=pcd-size-vs-fields
pcd_header "x y z intensity" "4 4 4" "F F F F" 1 1 ascii >"$M/sizes.pcd"
expect_detect_rejects "$M/sizes.pcd" "sizes\.pcd: line 3: SIZE has 3 entries but FIELDS has 4"

CASE=pcd-values-per-line
{ pcd_header "x y z intensity" "4 4 4 4" "F F F F" 2 2 ascii; printf '0 0 1 5\n0 0 1\n'; } >"$M/short_line.pcd"
expect_detect_rejects "$M/short_line.pcd" "short_line\.pcd: line 12: 3 values, the header declares 4"

CASE=pcd-not-a-number
{ pcd_header "x y z intensity" "4 4 4 4" "F F F F" 1 1 ascii; printf '0 zero 1 5\n'; } >"$M/word.pcd"
expect_detect_rejects "$M/word.pcd" "word\.pcd: line 11: field y: 'zero' is not a number"

CASE=pcd-wrong-magic
printf '\x89PNG\r\n\x1a\n\0\0\0\rIHDR' >"$M/image.pcd"
expect_detect_rejects "$M/image.pcd" "image\.pcd: line 1: not a PCD file"

CASE=pcd-empty-file
: >"$M/empty.pcd"
expect_detect_rejects "$M/empty.pcd" "empty\.pcd: header: file is empty"

CASE=pcd-no-intensity
{ pcd_header "x y z rgb" "4 4 4 4" "F F F F" 1 1 ascii; printf '0 0 1 5\n'; } >"$M/rgb.pcd"
expect_detect_rejects "$M/rgb.pcd" "rgb\.pcd: line 2: no intensity field .*the fields are: x y z rgb"

CASE=pcd-absurd-point-count
{ pcd_header "x y z intensity" "4 4 4 4" "F F F F" 1000000000000 1000000000000 binary; floats 10; } >"$M/huge.pcd"
expect_detect_rejects "$M/huge.pcd" "huge\.pcd: byte offset [0-9]+: truncated"

CASE=pcd-absurd-point-count-ascii
{ pcd_header "x y z intensity" "4 4 4 4" "F F F F" 1000000000000 1000000000000 ascii; printf '0 0 1 5\n'; } >"$M/huge_ascii.pcd"
expect_detect_rejects "$M/huge_ascii.pcd" "huge_ascii\.pcd: line [0-9]+: file ends after 1 of 1000000000000 points"

CASE=pcd-overflowing-point-count
pcd_header "x y z intensity" "4 4 4 4" "F F F F" 18446744073709551615 18446744073709551615 binary >"$M/overflow.pcd"
expect_detect_rejects "$M/overflow.pcd" "overflow\.pcd: header: POINTS [0-9]+ is absurdly large"

CASE=pcd-corrupt-lzf
{ pcd_header "x y z intensity" "4 4 4 4" "F F F F" 4 4 binary_compressed; perl -e 'print pack("V V", 8, 64), "\xff\xff\xff\xff\xff\xff\xff\xff"'; } >"$M/lzf.pcd"
expect_detect_rejects "$M/lzf.pcd" "lzf\.pcd: byte offset [0-9]+: corrupt LZF data"

CASE=pcd-bad-type
pcd_header "x y z intensity" "4 4 4 3" "F F F F" 1 1 binary >"$M/type.pcd"
expect_detect_rejects "$M/type.pcd" "type\.pcd: field intensity: TYPE F with SIZE 3"

# ---- PLY, KITTI, text, dispatch ---------------------------------------------
ply_header() { printf 'ply\nformat %s 1.0\nelement vertex %s\nproperty float x\nproperty float y\nproperty float z\nproperty float %s\nend_header\n' "$1" "$2" "$3"; }

CASE=ply-truncated-binary
{ ply_header binary_little_endian 100 intensity; floats 10; } >"$M/cut.ply"
expect_detect_rejects "$M/cut.ply" "cut\.ply: byte offset [0-9]+: truncated in element vertex"

CASE=ply-wrong-magic
{ printf 'plz\n'; ply_header ascii 1 intensity | tail -n +2; } >"$M/magic.ply"
expect_detect_rejects "$M/magic.ply" "magic\.ply: line 1: not a PLY file"

CASE=ply-no-intensity
{ ply_header ascii 1 red; printf '0 0 1 5\n'; } >"$M/red.ply"
expect_detect_rejects "$M/red.ply" "red\.ply: line 3: no intensity field .*the fields are: x y z red"

CASE=ply-absurd-count
{ ply_header ascii 1000000000000 intensity; printf '0 0 1 5\n'; } >"$M/huge.ply"
expect_detect_rejects "$M/huge.ply" "huge\.ply: line [0-9]+: file ends in element vertex after 1 of 1000000000000"

CASE=kitti-partial-record
floats 3 | head -c 40 >"$M/partial.bin"
expect_detect_rejects "$M/partial.bin" "partial\.bin: .*(40|16)"

CASE=xyzi-bad-number
printf '0 0 1 5\n0 0 1 five\n' >"$M/bad.xyzi"
expect_detect_rejects "$M/bad.xyzi" "bad\.xyzi: line 2: .*'five'"

CASE=unknown-extension
printf 'hello\n' >"$M/map.e57"
expect_detect_rejects "$M/map.e57" "map\.e57: unknown file extension '\.e57'; supported: .*\.las"

CASE=las-garbage
printf 'hello\n' >"$M/map.las"
expect_detect_rejects "$M/map.las" "map\.las: header: not a LAS file"

CASE=laz
printf 'hello\n' >"$M/map.laz"
expect_detect_rejects "$M/map.laz" "map\.laz: LAZ .*decompress it first.*laszip"

CASE=missing-input
expect_detect_rejects "$M/nowhere.pcd" "nowhere\.pcd: cannot open: No such file"

CASE=directory-input
mkdir -p "$M/dir.pcd"
expect_detect_rejects "$M/dir.pcd" "dir\.pcd: is not a regular file"

# ---- MRPT files (MRPT prints multi-line exceptions with stack traces) ------
CASE=simplemap-garbage
printf 'not a simplemap\n' >"$M/junk.simplemap"
expect_detect_rejects "$M/junk.simplemap" "junk\.simplemap: not a readable MRPT simplemap"

CASE=rawlog-garbage
printf 'not a rawlog\n' >"$M/junk.rawlog"
expect_detect_rejects "$M/junk.rawlog" "junk\.rawlog: object 1: not a readable MRPT rawlog"

CASE=rawlog-empty
: >"$M/empty.rawlog"
expect_detect_rejects "$M/empty.rawlog" "empty\.rawlog: empty rawlog"

# ---- skipped, not fatal ----------------------------------------------------
CASE=nan-inf-points-skipped
{ pcd_header "x y z intensity" "4 4 4 4" "F F F F" 4 4 ascii; printf '0 0 1 5\nnan 0 1 5\n0 inf 1 5\n0 0 1 -inf\n'; } >"$M/nan.pcd"
expect_detect_accepts "$M/nan.pcd" '"tags": \[\]'
grep -q "skipped 3 non-finite" <<<"$ERR" || fail "the skipped non-finite points are not reported: $ERR"

CASE=absurd-coordinates-skipped
{ pcd_header "x y z intensity" "4 4 4 4" "F F F F" 4 4 ascii; printf '0 0 1 5\n1e30 0 1 5\n0 -1e30 1 5\n0.5 0.5 1 6\n'; } >"$M/far.pcd"
expect_detect_accepts "$M/far.pcd" '"tags": \[\]'
grep -Eq "skipped 2 .*(far|range)" <<<"$ERR" || fail "the skipped far points are not reported: $ERR"

CASE=absurd-coordinates-binary
{ pcd_header "x y z intensity" "8 8 8 4" "F F F F" 3 3 binary; perl -e 'print pack("d< d< d< f<", 1e300, 0, 0, 1), pack("d< d< d< f<", 0, 0, 1, 1), pack("d< d< d< f<", 0, 1e7, 0, 1)'; } >"$M/far64.pcd"
expect_detect_accepts "$M/far64.pcd" '"tags": \[\]'

# Within the bound but 900 km from the rest: the neighbour index has no
# extent limit, the stray point simply has no neighbours.
CASE=stray-far-point
{
	pcd_header "x y z intensity" "4 4 4 4" "F F F F" 10001 10001 ascii
	perl -e 'for my $i (0 .. 99) { for my $j (0 .. 99) { printf "%.2f %.2f 1 %d\n", $i / 100, $j / 100, ($i + $j) % 2 * 50 } } print "900000 0 1 5\n"'
} >"$M/stray.pcd"
expect_detect_accepts "$M/stray.pcd" '"tags": \[\]'

# No usable point is not "no tags here": it fails, saying why.
CASE=empty-map
pcd_header "x y z intensity" "4 4 4 4" "F F F F" 0 0 binary >"$M/none.pcd"
expect_detect_rejects "$M/none.pcd" "none\.pcd: no usable point: read 0 points"

CASE=all-points-unusable
{ pcd_header "x y z intensity" "4 4 4 4" "F F F F" 2 2 ascii; printf 'nan 0 1 5\n1e30 0 1 5\n'; } >"$M/unusable.pcd"
expect_detect_rejects "$M/unusable.pcd" "unusable\.pcd: no usable point: read 2 points; skipped 1 non-finite .*, skipped 1 out of range"

finish
