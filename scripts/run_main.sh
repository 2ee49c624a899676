#!/usr/bin/env bash
# README command 1: installs what is missing, builds, and runs the main job: plan the scenario
# (default scenarios/humanoid_walk.yaml; the paper's desk scenario becomes the default once it
# plans), certify the plan, and render its steps, a figure strip and an animated GIF into
# ./stanceplan-out/. No display is needed (off-screen OSMesa rendering).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
scenario=${1:-$root/scenarios/humanoid_walk.yaml}
out=${STANCEPLAN_OUT:-$PWD/stanceplan-out}
"$root/scripts/bootstrap.sh"
"$root/scripts/build.sh"
bin="${BUILD_DIR:-$root/build}/app/stanceplan"
mkdir -p "$out"
"$bin" plan "$scenario" --out "$out/plan.json"
"$bin" certify "$out/plan.json"
"$bin" render "$out/plan.json" --out "$out/steps" --strip "$out/strip.png" --gif "$out/sequence.gif"
echo "main job done: plan $out/plan.json, step images $out/steps/, strip $out/strip.png, animation $out/sequence.gif"
