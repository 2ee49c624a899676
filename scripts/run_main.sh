#!/usr/bin/env bash
# README command 1: installs what is missing, builds, and runs the main job on the default
# scenario. The search does not exist yet (issue 4): for now the main job describes the default
# scenario's models (the humanoid and the desk room) with `stanceplan inspect`.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/bootstrap.sh"
"$root/scripts/build.sh"
bin="${BUILD_DIR:-$root/build}/app/stanceplan"
"$bin" inspect "$root/assets/robots/humanoid/humanoid.urdf" --kind floating \
  --surfaces "$root/assets/robots/humanoid/humanoid.surfaces.yaml"
"$bin" inspect "$root/assets/environments/desk_room/desk_room.urdf" --kind environment \
  --surfaces "$root/assets/environments/desk_room/desk_room.surfaces.yaml"
