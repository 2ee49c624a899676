#!/usr/bin/env bash
# README command 2: installs what is missing, builds everything and runs every test with CTest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/bootstrap.sh"
"$root/scripts/build.sh"
ctest --test-dir "${BUILD_DIR:-$root/build}" --output-on-failure -j "${JOBS:-$(nproc)}"
# ThreadSanitizer on the hand-off between the search thread and the snapshot thread (tests/app/live):
# a separate tree with -DSTANCEPLAN_SANITIZER=thread, building only that test executable.
if [[ "${STANCEPLAN_TSAN:-1}" != 0 ]]; then
  tsan_dir=${TSAN_BUILD_DIR:-$root/build-tsan}
  cmake -S "$root" -B "$tsan_dir" -DCMAKE_BUILD_TYPE=Release -DSTANCEPLAN_SANITIZER=thread \
    -DSTANCEPLAN_BUILD_BENCHMARKS=OFF >/dev/null
  cmake --build "$tsan_dir" -j "${JOBS:-$(nproc)}" --target app_live_test
  TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$root/tests/app/live/tsan.supp ${TSAN_OPTIONS:-}" \
    "$tsan_dir/tests/app_live_test" --gtest_filter='PlanSession.*:Snapshots.*'
fi
