#!/usr/bin/env bash
# SPHERIC Test 2 (Kleefsman et al. 2005): samples/spheric_test2.json at its 2.5 cm spacing and at
# the 5 cm of the CI test (tests/physics/test_spheric_test2.cpp), against the MARIN experiment.
# Prints each run's speed and the window means of its probes beside the measured ones, and draws
# OUT/spheric_test2.png (docs/images/spheric_test2.png is this picture).
#
# usage: bench/spheric_test2.sh [END_SECONDS=6] [OUT=out/bench_spheric_test2] [THREADS=2]
# Figures only: nothing here passes or fails.
set -euo pipefail
cd "$(dirname "$0")/.."
end=${1:-6}
out=${2:-out/bench_spheric_test2}
threads=${3:-2}
upf=build/release/apps/upf/upf
[[ -x $upf ]] || { echo "build first: make build" >&2; exit 1; }
mkdir -p "$out"
for spacing in 0.025 0.05; do
  dir="$out/s$spacing"
  "$upf" run samples/spheric_test2.json --out "$dir" -j "$threads" -q --no-frames \
    --end "$end" --set "/particle_spacing=$spacing" | head -1
done
/usr/bin/python3 scripts/plot-spheric-test2 "$out/spheric_test2.png" \
  "upf PCISPH, s = 2.5 cm=$out/s0.025" "upf PCISPH, s = 5 cm=$out/s0.05"
echo "picture: $out/spheric_test2.png"
