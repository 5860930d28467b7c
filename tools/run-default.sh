#!/usr/bin/env bash
# README command 1: set up, build and run the default low-velocity impact scene.
# Results go to results/low_velocity_impact/ (open low_velocity_impact.pvd in ParaView).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
./build/src/app/plyimpact run configs/low_velocity_impact.yaml -o results/low_velocity_impact
