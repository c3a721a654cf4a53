#!/usr/bin/env bash
# Fails when two headers define a namespace-scope type of the same name.
#
# Every module lives in namespace furrow and all of them link into one
# library, so two different `struct GougeSite` definitions are an ODR
# violation: the linker keeps one copy of their inline members and the other
# module silently uses the wrong layout (this crashed `furrow predict` once).
# Namespace-scope definitions start in column 0 in this code base (nested
# types are indented); forward declarations end with ';' and are ignored.
set -euo pipefail
cd "$(dirname "$0")/.."
dups=$(grep -rhoE '^(struct|class|enum class|enum|union) [A-Za-z_][A-Za-z_0-9]*[^;]*$' src --include='*.hpp' \
  | sed -E 's/^(struct|class|enum class|enum|union) ([A-Za-z_0-9]+).*/\2/' | sort | uniq -d)
if [ -n "$dups" ]; then
  echo "types defined in more than one header (rename one of each):"
  for t in $dups; do grep -rnE "^(struct|class|enum class|enum|union) $t\b[^;]*$" src --include='*.hpp'; done
  exit 1
fi
echo "check-unique-types: every namespace-scope type name is defined once"
