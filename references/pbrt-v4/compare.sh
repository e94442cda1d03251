#!/bin/sh
# One comparison of two of pbrt-v4's integrators on one scene, as reports/validation-findings.md tabulates it:
#   references/pbrt-v4/compare.sh VERITY SCENE INTEGRATOR_A INTEGRATOR_B [extra verity options]
# run from the repository root. Prints one table row: rejected tests, smallest p, the largest
# |z|, the whole-image bias detectable with 90% power, and the verdict.
set -u
verity=$1 scene=$2 a=$3 b=$4
shift 4
dir=references/pbrt-v4/$scene
out=$("$verity" compare --tile 8 "$@" -a "$dir/$a"/seed-*.exr -b "$dir/$b"/seed-*.exr 2>&1)
status=$?
rejected=$(printf '%s\n' "$out" | sed -n 's/^Holm-Bonferroni.*: \([0-9]* of [0-9]*\) tests rejected.*/\1/p')
smallest=$(printf '%s\n' "$out" | sed -n 's/^smallest p: //p')
power=$(printf '%s\n' "$out" | sed -n 's/^power: a uniform brightness bias of \([^ ]*\) would.*/\1/p')
verdict=$(printf '%s\n' "$out" | sed -n 's/^verdict: \([A-Z]*\).*/\1/p')
echo "| $scene | $b vs $a | $rejected | $smallest | $power | $verdict (status $status) |"
