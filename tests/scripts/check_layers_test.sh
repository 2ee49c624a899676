#!/usr/bin/env bash
# scripts/check_layers.sh on trees made for the test: a tree whose includes point down the layers
# passes; each rule broken once fails with its message.
set -euo pipefail
script=$(cd "$(dirname "$0")/../.." && pwd)/scripts/check_layers.sh
tree=$(mktemp -d)
trap 'rm -rf "$tree"' EXIT
mkdir -p "$tree"/planner/{model,search,io} "$tree"/render
echo '#include "planner/model/model.h"' >"$tree/planner/search/a.h"
echo '#include "planner/search/a.h"' >"$tree/planner/io/b.h"
echo '#include "planner/io/b.h"' >"$tree/render/c.h"
bash "$script" "$tree" >/dev/null || { echo "FAIL: a tree that keeps the layers was rejected"; exit 1; }

expect_failure() {  # file, include line, expected message
  local before
  before=$(cat "$tree/$1" 2>/dev/null || true)
  echo "$2" >>"$tree/$1"
  if out=$(bash "$script" "$tree" 2>&1); then
    echo "FAIL: $1 with '$2' passed"
    exit 1
  fi
  grep -qF "$3" <<<"$out" || { echo "FAIL: expected '$3', got: $out"; exit 1; }
  printf '%s\n' "$before" >"$tree/$1"
}
expect_failure planner/search/a.h '#include "planner/io/scenario.h"' \
  "planner/search/a.h includes planner/io/scenario.h: planner/search/ may include only the layers below it"
expect_failure planner/model/d.h '#include "render/renderer.h"' \
  "planner/model/d.h includes render/renderer.h: planner/ never includes render/, app/, GL, GLFW or ImGui"
expect_failure planner/io/b.h '#include <imgui.h>' \
  "planner/io/b.h includes imgui.h: planner/ never includes render/, app/, GL, GLFW or ImGui"
expect_failure render/c.h '#include "app/cli.h"' \
  "render/c.h includes app/cli.h: render/ never includes app/, GLFW or ImGui"
echo "check_layers_test: 1 passed tree, 4 rejected includes"
