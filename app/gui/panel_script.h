#pragma once
// A scripted panel session (`stanceplan panel SCENARIO --script FILE`): one action per line, run
// in order against the live window, for tests, figures and bug reports. Blank lines and text after
// '#' are ignored. The grammar (docs/README.md, "Scripting the panel"):
//
//   run | pause | cancel | rerun | quit
//   step event | step expansion | next milestone
//   speed N                  events per second while running, 0 = no limit
//   wait SECONDS             let the panel run (and the search, if running) this long
//   wait-for plan | failure | end | event N | motion
//   select node N | select event N | timeline POSITION   (a step, or 2.5: half-way to step 3)
//   orbit DX DY | zoom CLICKS | reset view     the mouse, driven through ImGui like a user's
//   tab inspector | tab plots
//   print                    one line: what the view and the inspector show (event, contacts)
//   screenshot FILE.png | export view | export strip
//
// Parsing is pure (no window): a bad line is an InputError naming the file, the line, what was
// expected and what was found, before the window opens.
#include <string>
#include <vector>

namespace stanceplan::gui {

enum class ScriptVerb {
  Run,
  Pause,
  Cancel,
  Rerun,
  Quit,
  StepEvent,
  StepExpansion,
  NextMilestone,
  Speed,
  Wait,
  WaitForPlan,
  WaitForFailure,
  WaitForEnd,
  WaitForEvent,
  WaitForMotion,
  SelectNode,
  SelectEvent,
  Timeline,
  Orbit,
  Zoom,
  ResetView,
  TabInspector,
  TabPlots,
  Print,
  Screenshot,
  ExportView,
  ExportStrip,
};

struct ScriptAction {
  ScriptVerb verb = ScriptVerb::Run;
  double a = 0.0, b = 0.0;  // the numbers the verb takes (speed, seconds, ids, pixels)
  std::string path;         // screenshot
  int line = 0;             // 1-based, in the script file
  std::string text;         // the line as written, without comment and outer blanks
};

// Reads and checks a script file. Throws InputError ("FILE:LINE: ...") on the first bad line, and
// when the file cannot be read or holds no action.
std::vector<ScriptAction> read_panel_script(const std::string& path);
// The same for text already in memory; `path` only names it in messages.
std::vector<ScriptAction> parse_panel_script(const std::string& text, const std::string& path);

}  // namespace stanceplan::gui
