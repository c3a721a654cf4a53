#!/usr/bin/env bash
# Collects the seed corpus of every fuzz target (docs/testing.md "Fuzz
# targets") into OUT/<target>/: the small seed files committed under
# fuzz/seeds/<target>/ plus the matching example and test inputs of the
# repository. The large line-based files (the example tool paths) are cut
# to their first lines, whole lines only: a seed shows the reader the format,
# and libFuzzer mutates small inputs much faster than large ones. JSON files
# are copied whole (cut, they would only test the JSON parser's error path).
#
# usage: fuzz-seeds.sh SOURCE_DIR OUT
set -euo pipefail
src=$1
out=$2
max_bytes=4096

# add TARGET FILE...: copy each FILE into OUT/TARGET, whole.
# add_cut TARGET FILE...: the same, text files cut to max_bytes (whole lines).
add() { cut_bytes=0 copy "$@"; }
add_cut() { cut_bytes=$max_bytes copy "$@"; }
copy() {
  local target=$1; shift
  mkdir -p "$out/$target"
  local f
  for f in "$@"; do
    [ -f "$f" ] || continue
    local name
    name=$(basename "$f")
    if [ "$cut_bytes" -eq 0 ] || [ "$(stat -c %s "$f")" -le "$cut_bytes" ]; then
      cp "$f" "$out/$target/$name"
    else
      head -c "$cut_bytes" "$f" | sed '$d' > "$out/$target/$name"
    fi
  done
}

for dir in "$src"/fuzz/seeds/*/; do
  [ -d "$dir" ] || continue
  add "$(basename "$dir")" "$dir"*
done
add part_json "$src"/examples/parts/*.json
add tool_json "$src"/examples/tools/{ball,bull,flat}_*.json
add tool_library_json "$src"/examples/tools/library.json
add tool_table_json "$src"/examples/tools/table.json
add_cut gcode "$src"/examples/toolpaths/*.nc
add_cut toolpath_csv "$src"/examples/toolpaths/*.csv
add job_json "$src"/examples/jobs/*.json
add dmis_program "$src"/tests/io/cmm/golden/*.dmi
add ippdme_program "$src"/tests/io/cmm/golden/*.prg
add measurements_dmis "$src"/tests/io/cmm/golden/*.dmi
# A libFuzzer dictionary for the JSON targets: JSON's own tokens and every
# short lower-case string literal of the sources that use the JSON helpers
# (base/json_fields.hpp: the member names and enumerated values of every
# Furrow JSON), written as JSON strings. Made from the sources at build time,
# so it follows the formats as they change.
mapfile -t json_sources < <(grep -rl --include='*.cpp' 'base/json_fields.hpp' "$src/src" | sort)
{
  printf '%s\n' '"{"' '"}"' '"["' '"]"' '":"' '","' '"true"' '"false"' '"null"' '"-0"' '"1e308"' \
    '"-1e-320"' '"\\u0000"'
  grep -ohE '"[a-z][a-z0-9_]{1,30}"' "${json_sources[@]}" | sort -u | sed 's/^"\(.*\)"$/"\\"\1\\""/'
} > "$out/json.dict"

echo "fuzz-seeds: $(find "$out" -mindepth 2 -type f | wc -l) seed files in $(find "$out" -mindepth 1 -type d | wc -l) corpora under $out"
