#!/usr/bin/env bash
# docs/ARCHITECTURE.md's library table against the CMake files: for each row,
# the tagmap_* targets listed must be exactly the tagmap_* targets that the
# target links (target_link_libraries, PUBLIC and PRIVATE alike); every
# library under libs/ must have a row; no target may link the plugin.
# Usage: check_architecture_deps.sh [SOURCE_DIR]
set -euo pipefail
src=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
doc=$src/docs/ARCHITECTURE.md
fail=0

# The CMake file that defines a target.
cmake_file_of() {
  grep -lE "add_(library|executable)\(\s*$1(\s|$)" "$src"/libs/*/CMakeLists.txt "$src"/plugins/CMakeLists.txt \
    "$src"/apps/*/CMakeLists.txt 2>/dev/null | head -1
}

# tagmap_* targets a target links, sorted, one per line.
linked_by() {
  local file=$1 target=$2
  # Join lines, cut out each target_link_libraries(<target> ...) call.
  tr '\n' ' ' <"$file" | grep -oE "target_link_libraries\(\s*$target\s[^)]*\)" |
    grep -oE '\btagmap_[a-z_]+\b' | grep -vx "$target" | sort -u || true
}

rows=$(grep -E '^\| tagmap_[a-z_]+ |^\| tagmap \(' "$doc" || true)
[ -n "$rows" ] || { echo "no library table in $doc"; exit 1; }

while IFS= read -r row; do
  target=$(echo "$row" | awk -F'|' '{print $2}' | awk '{print $1}')
  listed=$(echo "$row" | awk -F'|' '{print $3}' | grep -oE '\btagmap_[a-z_]+\b' | sort -u || true)
  file=$(cmake_file_of "$target")
  if [ -z "$file" ]; then echo "ARCHITECTURE.md lists $target, which no CMakeLists.txt defines"; fail=1; continue; fi
  actual=$(linked_by "$file" "$target")
  if [ "$listed" != "$actual" ]; then
    echo "$target: ARCHITECTURE.md says [$(echo $listed)], ${file#$src/} links [$(echo $actual)]"
    fail=1
  fi
done <<<"$rows"

# Every library has a row.
for f in "$src"/libs/*/CMakeLists.txt; do
  for t in $(tr '\n' ' ' <"$f" | grep -oE 'add_library\(\s*tagmap_[a-z_]+' | grep -oE 'tagmap_[a-z_]+'); do
    # A here-string, not `echo | grep -q`: grep -q exits at the first row,
    # and under pipefail echo's late write of the final newline then failed
    # with SIGPIPE now and then (tagmap_core, the first row, "had no row").
    grep -qE "^\| $t " <<<"$rows" || { echo "$t (${f#$src/}) has no row in ARCHITECTURE.md"; fail=1; }
  done
done

# Nothing links the plugin: it is loaded by MRPT apps, not linked.
for f in $(grep -rlE 'tagmap_mrpt_plugin' --include=CMakeLists.txt --include='*.cmake' "$src"/libs "$src"/apps "$src"/tests || true); do
  if grep -qE 'target_link_libraries\([^)]*tagmap_mrpt_plugin' <<<"$(tr '\n' ' ' <"$f")"; then
    echo "${f#$src/} links tagmap_mrpt_plugin"; fail=1
  fi
done

[ $fail = 0 ] && echo "ARCHITECTURE.md library table matches the CMake files ($(echo "$rows" | wc -l) targets)"
exit $fail
