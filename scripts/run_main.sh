#!/usr/bin/env bash
# README command 1: installs what is missing, builds, and runs the main job (`stanceplan
# [SCENARIO.yaml]`, app/live/main_job.h): with a display it opens the panel; without
# one it plans with live snapshots of every search event, certifies the plan and renders its
# steps, a figure strip and an animated GIF into ./stanceplan-out/ (off-screen OSMesa rendering).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# Without an argument: the program's default scenario (scenarios/humanoid_sit_desk.yaml).
scenario=${1:-}
out=${STANCEPLAN_OUT:-$PWD/stanceplan-out}
"$root/scripts/bootstrap.sh"
"$root/scripts/build.sh"
bin="${BUILD_DIR:-$root/build}/app/stanceplan"
"$bin" ${scenario:+"$scenario"} --out "$out"
