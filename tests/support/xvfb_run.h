#pragma once
// `stanceplan ARGS` in a virtual X server (xvfb-run), as a subprocess: for tests of the panel's
// window. The log holds stdout and stderr.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace stanceplan::test {

// xvfb-run from PATH, or "" when it is not installed.
inline std::string find_xvfb_run() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path != nullptr ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(dir) / "xvfb-run";
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec)) return candidate.string();
  }
  return "";
}

struct XvfbRun {
  int code = -1;
  std::string log;
};

// Runs `command` (a program and its arguments, or `sh -c '...'`) in a 1280x720 virtual screen;
// stdout and stderr go to the log.
inline XvfbRun run_command_in_xvfb(const std::string& command_line,
                                   const std::filesystem::path& dir) {
  const std::string xvfb = find_xvfb_run();
  const std::filesystem::path log = dir / "log.txt";
  // -a finds a free display from -n on: starting each test process at its own number keeps
  // parallel test cases from racing for the same one.
  const std::string first_display = std::to_string(100 + getpid() % 5000);
  // Under AddressSanitizer (the CI's ASan pass) leak checking is off for the window process only:
  // Mesa's GLX/DRI side keeps a few hundred bytes per process that it never frees, allocated in
  // libraries GLFW has unloaded by exit, so no suppression can name them (measured: 592 bytes in 7
  // objects, libOSMesa and unknown modules). Every other ASan check stays on, and the panel's
  // classes are leak-checked in-process by the other tests of this folder.
  const std::string asan = "ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" ";
  // The X authority file in the test's own folder (-f): left to itself xvfb-run makes a temporary
  // folder for it and, when removing that folder fails at exit (seen once in CI), exits 5 whatever
  // the command returned.
  const std::string auth = (dir / "Xauthority").string();
  const std::string command = asan + xvfb + " -a -n " + first_display + " -f " + auth +
                              " -s \"-screen 0 1280x720x24\" " + command_line + " > " +
                              log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  XvfbRun run;
  run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log);
  run.log.assign(std::istreambuf_iterator<char>(in), {});
  return run;
}

// Runs `stanceplan ARGS` in a virtual screen.
inline XvfbRun run_in_xvfb(const std::string& args, const std::filesystem::path& dir) {
  return run_command_in_xvfb(std::string(STANCEPLAN_BINARY) + " " + args, dir);
}

}  // namespace stanceplan::test
