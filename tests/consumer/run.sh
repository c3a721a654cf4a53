#!/usr/bin/env bash
# Installs the build tree into a scratch prefix, then configures, builds and
# runs tests/consumer against it. Args: BUILD_DIR WORK_DIR.
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
cmake -S "$here" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/build" >/dev/null
"$work/build/consumer"
