#include "app/gui/panel_script.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "planner/util/input_error.h"

namespace stanceplan::gui {
namespace {

// What a verb's arguments are.
enum class Args { None, Count, NonNegative, Positive, Index, Pixels, Clicks, PngPath };

struct VerbSpec {
  const char* words;  // the verb as written ("step event")
  ScriptVerb verb;
  Args args;
};

constexpr VerbSpec kVerbs[] = {
    {"run", ScriptVerb::Run, Args::None},
    {"pause", ScriptVerb::Pause, Args::None},
    {"cancel", ScriptVerb::Cancel, Args::None},
    {"rerun", ScriptVerb::Rerun, Args::None},
    {"quit", ScriptVerb::Quit, Args::None},
    {"step event", ScriptVerb::StepEvent, Args::None},
    {"step expansion", ScriptVerb::StepExpansion, Args::None},
    {"next milestone", ScriptVerb::NextMilestone, Args::None},
    {"speed", ScriptVerb::Speed, Args::NonNegative},
    {"wait", ScriptVerb::Wait, Args::Positive},
    {"wait-for plan", ScriptVerb::WaitForPlan, Args::None},
    {"wait-for failure", ScriptVerb::WaitForFailure, Args::None},
    {"wait-for end", ScriptVerb::WaitForEnd, Args::None},
    {"wait-for event", ScriptVerb::WaitForEvent, Args::Count},
    {"wait-for motion", ScriptVerb::WaitForMotion, Args::None},
    {"select node", ScriptVerb::SelectNode, Args::Index},
    {"select event", ScriptVerb::SelectEvent, Args::Index},
    {"timeline", ScriptVerb::Timeline, Args::NonNegative},
    {"orbit", ScriptVerb::Orbit, Args::Pixels},
    {"zoom", ScriptVerb::Zoom, Args::Clicks},
    {"reset view", ScriptVerb::ResetView, Args::None},
    {"tab inspector", ScriptVerb::TabInspector, Args::None},
    {"tab plots", ScriptVerb::TabPlots, Args::None},
    {"print", ScriptVerb::Print, Args::None},
    {"screenshot", ScriptVerb::Screenshot, Args::PngPath},
    {"export view", ScriptVerb::ExportView, Args::None},
    {"export strip", ScriptVerb::ExportStrip, Args::None},
};

const char* expected_args(Args args) {
  switch (args) {
    case Args::None:
      return "nothing after it";
    case Args::Count:
      return "a count (an integer >= 1)";
    case Args::NonNegative:
      return "a number >= 0";
    case Args::Positive:
      return "a number of seconds > 0";
    case Args::Index:
      return "an index (an integer >= 0)";
    case Args::Pixels:
      return "two numbers of pixels, DX DY";
    case Args::Clicks:
      return "a number of wheel clicks (non-zero; negative zooms out)";
    case Args::PngPath:
      return "a file name ending in .png";
  }
  return "";
}

std::vector<std::string> split_words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

bool parse_number(const std::string& word, double* value) {
  std::istringstream in(word);
  double v = 0.0;
  char extra = 0;
  if (!(in >> v) || (in >> extra) || !std::isfinite(v)) return false;
  *value = v;
  return true;
}

// The longest verb the line's words start with, or null.
const VerbSpec* match_verb(const std::vector<std::string>& words, size_t* used) {
  const VerbSpec* best = nullptr;
  for (const VerbSpec& spec : kVerbs) {
    const std::vector<std::string> verb = split_words(spec.words);
    if (verb.size() > words.size() || (best && verb.size() <= *used)) continue;
    bool same = true;
    for (size_t i = 0; i < verb.size() && same; ++i) same = verb[i] == words[i];
    if (!same) continue;
    best = &spec;
    *used = verb.size();
  }
  return best;
}

// Checks and stores the arguments; false when they are not what the verb takes.
bool read_args(const VerbSpec& spec, const std::vector<std::string>& args, ScriptAction* action) {
  double x = 0.0, y = 0.0;
  const auto is_integer = [](double v) { return v == std::floor(v); };
  switch (spec.args) {
    case Args::None:
      return args.empty();
    case Args::PngPath:
      if (args.size() != 1 || args[0].size() < 5) return false;
      action->path = args[0];
      return args[0].compare(args[0].size() - 4, 4, ".png") == 0;
    case Args::Pixels:
      if (args.size() != 2 || !parse_number(args[0], &x) || !parse_number(args[1], &y))
        return false;
      action->a = x;
      action->b = y;
      return true;
    default:
      break;
  }
  if (args.size() != 1 || !parse_number(args[0], &x)) return false;
  action->a = x;
  switch (spec.args) {
    case Args::Count:
      return x >= 1.0 && is_integer(x) && x < 1e9;
    case Args::NonNegative:
      return x >= 0.0;
    case Args::Positive:
      return x > 0.0;
    case Args::Index:
      return x >= 0.0 && is_integer(x) && x < 1e9;
    case Args::Clicks:
      return x != 0.0 && std::abs(x) <= 100.0;
    default:
      return false;
  }
}

std::string trimmed(const std::string& line) {
  const std::string text = line.substr(0, line.find('#'));
  const size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

ScriptAction parse_line(const std::string& text, const std::string& path, int line) {
  const std::string where = path + ":" + std::to_string(line) + ": ";
  const std::vector<std::string> words = split_words(text);
  size_t used = 0;
  const VerbSpec* spec = match_verb(words, &used);
  if (spec == nullptr)
    throw InputError(where +
                     "expected an action (run, pause, step event, wait SECONDS, ...: "
                     "docs/README.md), found \"" +
                     text + "\"");
  ScriptAction action;
  action.verb = spec->verb;
  action.line = line;
  action.text = text;
  const std::vector<std::string> args(words.begin() + long(used), words.end());
  if (!read_args(*spec, args, &action)) {
    std::string found;
    for (const std::string& a : args) found += (found.empty() ? "" : " ") + a;
    throw InputError(where + "\"" + spec->words + "\" takes " + expected_args(spec->args) +
                     ", found " + (found.empty() ? "nothing" : "\"" + found + "\""));
  }
  return action;
}

}  // namespace

std::vector<ScriptAction> parse_panel_script(const std::string& text, const std::string& path) {
  std::vector<ScriptAction> actions;
  std::istringstream in(text);
  int line = 0;
  for (std::string raw; std::getline(in, raw);) {
    ++line;
    const std::string clean = trimmed(raw);
    if (!clean.empty()) actions.push_back(parse_line(clean, path, line));
  }
  if (actions.empty())
    throw InputError(path + ": expected at least one action, found none (" + std::to_string(line) +
                     " lines of blanks and comments)");
  return actions;
}

std::vector<ScriptAction> read_panel_script(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot read the panel script (no such file, or no access)");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_panel_script(text.str(), path);
}

}  // namespace stanceplan::gui
