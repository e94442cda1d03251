#!/usr/bin/env bash
# A renderer's render-regression job: the same steps as referee.yml, as a plain script for any
# CI system (or a developer's machine).
#
#   examples/ci/referee-ci.sh VERITY_SOURCE MANIFEST [OUT]
#
# VERITY_SOURCE: a checkout of Verity; its program is built there (Debian packages installed
# as its README says) and installed to $VERITY_PREFIX/bin (default $HOME/.local), unless one
# built from the same commit is installed already (a CI cache of that folder).
# MANIFEST: the renderer's suite of comparisons (docs/referee.md, "CI: manifests"): its
# baselines restored beside it beforehand, and paths relative to it.
# OUT: where the JUnit, the JSON and the z-images go (default referee-out), to publish.
#
# Exit status: the referee's (0 every entry EQUIVALENT, 1 some DIFFER, 3 some INCONCLUSIVE,
# 2 bad input or a render that failed or ran past --render-timeout); the reports are written
# whatever it is.
set -euo pipefail
if [[ $# -lt 2 || $# -gt 3 ]]; then
  echo "usage: examples/ci/referee-ci.sh VERITY_SOURCE MANIFEST [OUT]" >&2
  exit 2
fi
source_dir=$(realpath "$1")
manifest=$2
out=${3:-referee-out}
prefix=${VERITY_PREFIX:-$HOME/.local}
commit=$(git -C "$source_dir" rev-parse HEAD)

# 1. Install Verity's program, once per Verity commit.
if [[ "$(cat "$prefix/share/verity-ci-commit" 2>/dev/null)" != "$commit" ]]; then
  "$source_dir/scripts/bootstrap" verity
  install -D "$source_dir/build/bin/verity" "$prefix/bin/verity"
  mkdir -p "$prefix/share" && echo "$commit" > "$prefix/share/verity-ci-commit"
fi

# 2. Run the suite: every entry's renders two at a time per core pair, a hung render killed
#    after 10 minutes and the whole run ended after an hour (INCONCLUSIVE for what is left).
mkdir -p "$out"
status=0
"$prefix/bin/verity" referee --manifest "$manifest" --jobs "$(nproc)" \
  --render-timeout 600 --max-seconds 3600 \
  --junit "$out/referee.xml" --json "$out/referee.json" --z-image "$out/z.png" || status=$?
echo "referee: exit status $status; reports in $out/"
exit $status
