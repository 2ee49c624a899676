#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang -O1, -DSTANCEPLAN_FUZZ=ON) and runs each one for
# FUZZ_SECONDS (default 60), JOBS of them at a time (default: the cores), each on one core, starting
# from the seed corpus made at configure time.
# New corpus entries go to FUZZ_BUILD_DIR/fuzz/corpus-out/TARGET (not into the source tree); a
# crash leaves crash-* / leak-* / oom-* / timeout-* in FUZZ_BUILD_DIR/fuzz/artifacts/ and fails
# the script (fuzz/lsan.supp lists a third-party leak on an error path).
# FUZZ_SEED (default 1) fixes libFuzzer's mutations, so that a run from a fresh corpus-out folder
# replays the same inputs as the last one (CI's short run is a regression gate, not a lottery);
# hunt for new faults with FUZZ_SEED=0 (random) and a longer FUZZ_SECONDS.
# Usage: scripts/run_fuzz.sh [TARGET...]  (default: scenario surfaces plan urdf srdf request)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${FUZZ_BUILD_DIR:-$root/build-fuzz}
seconds=${FUZZ_SECONDS:-60}
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(scenario surfaces plan urdf srdf request)

CC=clang-14 CXX=clang++-14 cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DSTANCEPLAN_FUZZ=ON "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" \
  -DSTANCEPLAN_BUILD_TESTS=OFF -DSTANCEPLAN_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$build_dir" -j "${JOBS:-$(nproc)}" --target "${targets[@]/#/fuzz_}"

artifacts="$build_dir/fuzz/artifacts"
mkdir -p "$artifacts"
# One target: one process on one core, its log in FUZZ_BUILD_DIR/fuzz/TARGET.log. -timeout: no input
# may take 10 s; -rss_limit_mb: ASan's shadow memory.
fuzz_one() {
  local t=$1 out="$build_dir/fuzz/corpus-out/$1" log="$build_dir/fuzz/$1.log"
  mkdir -p "$out"
  LSAN_OPTIONS="suppressions=$root/fuzz/lsan.supp ${LSAN_OPTIONS:-}" "$build_dir/fuzz/fuzz_$t" "$out" "$build_dir/fuzz/corpus/$t" -max_total_time="$seconds" -seed="${FUZZ_SEED:-1}" -timeout=10 \
    -rss_limit_mb=4096 -artifact_prefix="$artifacts/$t-" -print_final_stats=1 >"$log" 2>&1
}
report() {  # target, exit status: its summary; the log's tail and a failure when it found a fault
  local t=$1 status=$2 log="$build_dir/fuzz/$1.log"
  echo "fuzz: $t for ${seconds} s"
  grep -E "^(#[0-9]+.*DONE|stat::number_of_executed_units|stat::average_exec_per_sec|Done [0-9]+ runs)|ERROR|SUMMARY" "$log" | tail -8 || true
  if [ "$status" -ne 0 ]; then
    tail -60 "$log" >&2
    echo "fuzz: $t found a fault (exit $status); the input is in $artifacts" >&2
    return 1
  fi
}
# The targets run JOBS (default: the cores) at a time, each on its own core: with the seed fixed,
# a target replays the same inputs whatever runs beside it, only as many as its time allows.
jobs=${JOBS:-$(nproc)}
failed=0
for ((first = 0; first < ${#targets[@]}; first += jobs)); do
  batch=("${targets[@]:first:jobs}")
  pids=()
  for t in "${batch[@]}"; do
    fuzz_one "$t" &
    pids+=($!)
  done
  for i in "${!batch[@]}"; do
    status=0
    wait "${pids[$i]}" || status=$?
    report "${batch[$i]}" "$status" || failed=1
  done
done
exit "$failed"
