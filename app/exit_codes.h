#pragma once
// The exit codes of every `stanceplan` command (docs/ARCHITECTURE.md, Conventions).
namespace stanceplan::app {

enum ExitCode { kExitSuccess = 0, kExitBadInput = 1, kExitFailed = 2 };

}  // namespace stanceplan::app
