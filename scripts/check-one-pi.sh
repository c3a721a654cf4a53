#!/usr/bin/env bash
# Lint: in the library and CLI, pi is written once, in src/base/numbers.hpp
# (kPi, radians(), degrees()); every other source file uses it, so no two
# files can disagree on it or on the degree conversion. Tests and benches may
# write their own (an oracle independent of the code's constant). Exits 1
# listing each other definition or use of M_PI or a written-out pi in src/.
cd "$(dirname "$0")/.." || exit 2
hits=$(grep -rnE 'M_PI\b|3\.14159' src --include='*.cpp' --include='*.hpp' | grep -v '^src/base/numbers.hpp:')
if [ -n "$hits" ]; then
  echo "pi written outside src/base/numbers.hpp (use kPi, radians(), degrees()):"
  echo "$hits"
  exit 1
fi
