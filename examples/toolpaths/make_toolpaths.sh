#!/bin/sh
# Re-creates the example tool paths with the furrow CLI (run from the
# repository root after building: cmake --build build).
#   mould_ball6.nc / .csv  finishing path for the mould: ball 6 mm,
#                          tolerance 0.01 mm per step, scallop 0.005 mm,
#                          iso-parametric passes along u
set -e
furrow=${FURROW:-./build/furrow}
"$furrow" toolpath examples/parts/mould.json --tool examples/tools/ball_d6.json \
  --tolerance 0.01 --scallop 0.005 --direction u --out examples/toolpaths/mould_ball6.nc
