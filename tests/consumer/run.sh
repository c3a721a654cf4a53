#!/usr/bin/env bash
# Installs the build tree into a scratch prefix, then configures, builds and
# runs tests/consumer against it; the installed CLI and the installed shared
# library must both find the installed CAD module. Args: BUILD_DIR WORK_DIR.
set -euo pipefail
build=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
test -x "$work/prefix/bin/furrow"
test -f "$work/prefix/share/man/man1/furrow.1"
test -f "$work/prefix/share/bash-completion/completions/furrow"
ls "$work"/prefix/lib*/libfurrow_core.a "$work"/prefix/lib*/libfurrow_core.so >/dev/null
# Installed headers include one another as "furrow/...", never by a bare
# module folder ("geometry/..."), which a consumer's own folders could shadow.
modules='base|geometry|io|render|partition|machining|planning|inspection|report|stage|job'
if grep -rEn "#include \"($modules)/" "$work"/prefix/include/furrow; then
  echo "installed headers include Furrow's folders without the furrow/ prefix" >&2
  exit 1
fi
test ! -e "$work/prefix/include/furrow/cli"
cmake -S "$here" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/build" >/dev/null
step="$here/../bad_inputs/cad/points_only.step"
# Moved away from the build tree, so nothing there can be found instead.
mv "$work/prefix" "$work/moved"
module=$(ls "$work"/moved/lib*/furrow/furrow_cad.so)
LD_LIBRARY_PATH=$(dirname "$(dirname "$module")") "$work/build/consumer" "$step"
set +e
"$work/moved/bin/furrow" import "$step" --out "$work/part.json" 2> "$work/import.err"
status=$?
set -e
grep -q "no shape to import" "$work/import.err" || { cat "$work/import.err"; exit 1; }
test "$status" -eq 2
