#!/usr/bin/env bash
# The README's TALOS figures, made by the program itself from tests/data/talos/talos_walk.yaml
# (TALOS as published, read from ../shared/robots/talos beside the checkout, never copied here):
#   screenshots/talos.png             the half_sitting start: `posture`, then `render --view front`
#   screenshots/talos_walk_strip.png  the 1 m walk: `plan`, then `render --strip --view side`
# Skipped, with a message and exit 0, when ../shared/robots/talos is absent.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${STANCEPLAN:-$root/build/app/stanceplan}
cd "$root"
talos=$(cd "$root/.." && pwd)/shared/robots/talos
if [ ! -d "$talos" ]; then
  echo "talos_figures.sh: skipped: needs ../shared/robots/talos (the shared robot models beside" \
    "the checkout): $talos is absent" >&2
  exit 0
fi
scenario=tests/data/talos/talos_walk.yaml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$bin" posture "$scenario" --out "$work/posture.json"
"$bin" render "$work/posture.json" --out "$work/posture" --view front --size 1024x768
cp "$work/posture/step_000.png" screenshots/talos.png
"$bin" plan "$scenario" --out "$work/talos_walk.json"
"$bin" render "$work/talos_walk.json" --out "$work/steps" --view side \
  --strip screenshots/talos_walk_strip.png
