#!/usr/bin/env bash
# The one-way layers of docs/ARCHITECTURE.md, checked over every #include of the source tree.
# Exit 1, naming each include that points the wrong way:
#  - planner/ never includes render/, app/, GL, GLFW or ImGui; render/ never includes app/, GLFW
#    or ImGui;
#  - inside planner/, a folder includes only its own layer and those below it:
#      util < model < contact, collision < scene < solver < plan < search, guide, motion < io < certify
#    (so the search never includes io/, the file readers and writers, and the search and the
#    computed guide (planner/guide/) never include each other, nor motion/: the guide hands the search milestones
#    through the problem, as a scenario's guide: section does).
# KNOWN lists the includes that break a rule today and are still to be moved; it may only shrink.
# Usage: check_layers.sh [ROOT]  (ROOT: the tree to check, default this repository)
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root"

# Rank of each planner/ folder (bash builtins only: this runs over thousands of includes).
declare -A RANK=([util]=0 [model]=1 [contact]=2 [collision]=2 [scene]=3 [solver]=4 [plan]=5
                 [search]=6 [guide]=6 [motion]=6 [io]=7 [certify]=8)

# "file:included path" entries; none today.
KNOWN=()

violations=()
report() {  # file, included path, why
  local key="$1:$2"
  for k in "${KNOWN[@]}"; do [[ "$k" == "$key" ]] && return 0; done
  violations+=("$1 includes $2: $3")
}

while IFS= read -r line; do
  file=${line%%:*}
  include_re='#[[:space:]]*include[[:space:]]*[<"]([^>"]+)[>"]'
  [[ "$line" =~ $include_re ]] || continue
  included=${BASH_REMATCH[1]}
  case "$file" in
    planner/*)
      if [[ "$included" =~ ^(render|app)/ || "$included" =~ ^(GL|GLFW)/ || "$included" =~ imgui ]]; then
        report "$file" "$included" "planner/ never includes render/, app/, GL, GLFW or ImGui"
      elif [[ "$included" =~ ^planner/([a-z_]+)/ ]]; then
        to=${BASH_REMATCH[1]}
        from=${file#planner/}
        from=${from%%/*}
        if [[ "$to" != "$from" && ${RANK[$to]:-99} -ge ${RANK[$from]:-99} ]]; then
          report "$file" "$included" "planner/$from/ may include only the layers below it"
        fi
      fi
      ;;
    render/*)
      if [[ "$included" =~ ^app/ || "$included" =~ ^GLFW/ || "$included" =~ imgui ]]; then
        report "$file" "$included" "render/ never includes app/, GLFW or ImGui"
      fi
      ;;
  esac
done < <(grep -rnE --include='*.h' --include='*.cpp' '^[[:space:]]*#[[:space:]]*include' planner render |
         sed -E 's/^([^:]+):[0-9]+:/\1:/')

# A KNOWN entry that no longer occurs is stale: drop it from the list.
for k in "${KNOWN[@]}"; do
  file=${k%%:*}
  grep -qE "#[[:space:]]*include[[:space:]]*\"${k#*:}\"" "$file" 2>/dev/null ||
    violations+=("scripts/check_layers.sh: KNOWN lists $k, which no longer occurs: remove it")
done

if ((${#violations[@]})); then
  printf 'check_layers: %s\n' "${violations[@]}" >&2
  exit 1
fi
echo "check_layers: every include of planner/ and render/ points down the layers"
