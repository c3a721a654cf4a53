#!/usr/bin/env bash
# Installs the Debian packages Furrow builds and tests with (as root, or with
# sudo). Packages already present are not touched, so a second run is fast.
set -euo pipefail

packages=(
  build-essential cmake
  libeigen3-dev libceres-dev libnanoflann-dev libopencv-dev libpng-dev nlohmann-json3-dev doctest-dev
  libocct-data-exchange-dev libocct-modeling-algorithms-dev libssl-dev
  libpugixml-dev
  # dense scans (PLY, PCD): PCL, in the scan module furrow_scan.so only
  libpcl-dev
  # the results database: SQLite (src/results/sqlite_*) and PostgreSQL's
  # client library (src/results/postgres_*)
  libsqlite3-dev libpq-dev
  # tests only: the PostgreSQL tests start a throwaway cluster with its
  # initdb and pg_ctl (tests/results/postgres_cluster.hpp)
  postgresql
  # the QA report's 3D view inlines three.js; `furrow report --pdf` prints
  # with headless Chromium
  libjs-three chromium
  # tests only: report.json is checked against its schema by an independent
  # validator; report.pdf's pages are rendered and read with poppler-utils
  python3-jsonschema poppler-utils
  # tests only: every QIF document Furrow writes is validated against the
  # official QIF 3.0 XSD with xmllint (docs/qif.md "Validity")
  libxml2-utils
  # CI only: the sanitizer and fuzz build (docs/testing.md) - clang, its
  # sanitizer runtimes, libFuzzer and clang's OpenMP runtime
  clang-14 libclang-rt-14-dev libfuzzer-14-dev libomp-14-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

run() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
run apt-get update -qq
run apt-get install -y -qq "${missing[@]}" >/dev/null
echo "install-deps: done"
