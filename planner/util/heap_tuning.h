#pragma once
// The process's malloc settings for the solvers, set by the application (app/main.cpp) and the
// benchmarks at start-up, never by a library class behind its user's back.

namespace stanceplan {

// Every IK-statics solve factorises its KKT system with MUMPS, which allocates its workspace
// (megabytes) at each factorisation and frees it after: glibc then trims the heap's top back to
// the kernel (brk) and takes it again at the next factorisation, page faults and page-table
// teardown included. perf on the walk's motion: 25-30 % of the time in sysmalloc, brk and the
// kernel's page-table code. Keeping freed memory (up to 256 MB at the heap's top; workspaces below
// 32 MB from the heap) lets the next factorisation reuse it. Process-wide (forked solver workers
// inherit it); idempotent.
void keep_freed_heap_for_solvers();

}  // namespace stanceplan
