#!/bin/bash
# Instructions executed per solve of bench/solver_bench's programs (callgrind), for comparing
# solver changes on a machine whose timings are noisy: Cold/n is one cold solve (with the scene's
# set-up), Warm/n and WarmConfigurationOnly/n are reported as their benchmark minus Cold/n (the
# warm benchmarks first solve the cold program once). Usage:
#   scripts/solver_instructions.sh [build/bench/solver_bench]
# Environment switches (bench/solver_switches.h) apply, e.g. STANCEPLAN_NO_BALANCE=1.
set -euo pipefail
bench=${1:-build/bench/solver_bench}
command -v valgrind >/dev/null || { echo "valgrind is not installed (apt-get install valgrind)" >&2; exit 1; }
instructions() {  # benchmark name -> "instructions iterations"
  local out
  out=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null --toggle-collect="*BM_$1*" \
        "$bench" --benchmark_filter="BM_$1/$2\$" --benchmark_min_time=0.000001 2>&1)
  echo "$(echo "$out" | awk '/Collected/ {gsub(",", "", $4); print $4}') \
$(echo "$out" | grep -oE 'iterations=[0-9]+' | head -1 | cut -d= -f2)"
}
for n in 2 3 4; do
  read -r cold cold_it < <(instructions Cold $n)
  read -r warm warm_it < <(instructions Warm $n)
  read -r only only_it < <(instructions WarmConfigurationOnly $n)
  echo "$n contacts: cold $((cold / 1000000)) M ($cold_it iterations), warm $(((warm - cold) / 1000000)) M ($warm_it), configuration only $(((only - cold) / 1000000)) M ($only_it)"
done
