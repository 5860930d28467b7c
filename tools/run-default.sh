#!/usr/bin/env bash
# README command 1: set up, build and run the default scene, the seed's low-velocity impact study
# (configs/low_velocity_impact.yaml: ASTM D7136 T800S/M21 plate, rigid 16 mm tup, 26.8 J, the whole
# event, until the force along the tup's axis is back to zero). About 4 to 5 minutes (after the
# build) on the project's 2-core machine.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
out=results/low_velocity_impact
status=0
./build/src/app/plyimpact run configs/low_velocity_impact.yaml -o "$out" || status=$?
# Exit code 2: the run stopped early; what was written so far is kept and summary.json says why.
echo
echo "Results in $PWD/$out/:"
echo "  low_velocity_impact.pvd  frames for ParaView (Threshold on 'alive' hides eroded elements)"
echo "  history.csv              energies, contact force (contact_tup_plies_*), tup motion, eroded count"
echo "  summary.json             run summary: status, energies, erosion per part and cause"
exit "$status"
