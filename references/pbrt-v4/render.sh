#!/bin/sh
# Renders one scene of scenes/pbrt-v4/ with one integrator variant for seeds FIRST..LAST:
#   references/pbrt-v4/render.sh PBRT SCENE INTEGRATOR FIRST LAST [SPP]
# run from the repository root. PBRT is a pbrt-v4 binary built outside this repository
# (references/pbrt-v4/README.md says which and how). Writes
# references/pbrt-v4/SCENE/INTEGRATOR/seed-N.exr (pbrt's own EXR: half floats R, G, B).
set -eu
pbrt=$1 scene=$2 integrator=$3 first=$4 last=$5 spp=${6:-}
out=references/pbrt-v4/$scene/$integrator
mkdir -p "$out"
seed=$first
while [ "$seed" -le "$last" ]; do
  $pbrt --nthreads 2 --quiet --seed "$seed" ${spp:+--spp "$spp"} \
    --outfile "$out/seed-$seed.exr" \
    "scenes/pbrt-v4/integrators/$integrator.pbrt" "scenes/pbrt-v4/$scene.pbrt"
  seed=$((seed + 1))
done
