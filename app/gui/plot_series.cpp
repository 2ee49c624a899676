#include "app/gui/plot_series.h"

#include <algorithm>
#include <map>

#include "app/gui/node_details.h"

namespace stanceplan::gui {
namespace {

void add_candidate(SearchSeries& s, const SearchEvent& e, long index) {
  const double x = e.number;
  PlotSeries& time = e.accepted ? s.accepted_time_ms : s.rejected_time_ms;
  PlotSeries& iterations = e.accepted ? s.accepted_iterations : s.rejected_iterations;
  time.points.push_back({x, e.time_ms, index, {}});
  iterations.points.push_back({x, static_cast<double>(e.iterations), index, {}});
}

// Failure events carry no milestone (their field stays 0): they do not move the staircase.
void add_milestone_target(PlotSeries& stairs, const SearchEvent& e, long index) {
  if (e.kind == SearchEventKind::Failure) return;
  std::vector<PlotPoint>& p = stairs.points;
  // Keep the first point of each level and the newest event: a staircase needs no more.
  if (p.size() >= 2 && p[p.size() - 2].y == e.milestone && p.back().y == e.milestone)
    p.back() = {double(e.number), double(e.milestone), index, {}};
  else
    p.push_back({double(e.number), double(e.milestone), index, {}});
}

// The joint with the largest torque ratio, as "entity joint", for the hover readout.
std::string worst_joint(const NodeDetails& d) {
  const TorqueRow* worst = nullptr;
  for (const TorqueRow& t : d.torques)
    if (t.effort > 0.0 && (worst == nullptr || t.ratio() > worst->ratio())) worst = &t;
  return worst ? worst->entity + " " + worst->joint : "";
}

}  // namespace

SearchSeries search_series(const std::vector<SearchEvent>& events) {
  SearchSeries s;
  s.accepted_time_ms.name = "accepted";
  s.rejected_time_ms.name = "rejected";
  s.accepted_iterations.name = "accepted";
  s.rejected_iterations.name = "rejected";
  s.milestone_target.name = "milestone targeted";
  s.milestones_reached.name = "milestone reached";
  for (size_t i = 0; i < events.size(); ++i) {
    const SearchEvent& e = events[i];
    const long index = static_cast<long>(i);
    if (e.kind == SearchEventKind::Candidate) add_candidate(s, e, index);
    if (e.kind == SearchEventKind::Milestone || e.kind == SearchEventKind::PlanFound)
      s.milestones_reached.points.push_back({double(e.number), double(e.milestone), index,
                                             e.kind == SearchEventKind::PlanFound ? "goal reached"
                                             : skipped_milestone(e) ? "milestone skipped"
                                                                    : "milestone reached"});
    add_milestone_target(s.milestone_target, e, index);
  }
  return s;
}

PlanSeries plan_series(const Scene& scene, const std::vector<SearchEvent>& events,
                       const SearchTree& tree, const Plan& plan) {
  PlanSeries s;
  s.worst_torque_ratio.name = "worst torque / effort";
  const std::vector<int> path = tree.plan_path();
  const size_t steps = std::min(path.size(), plan.steps.size());
  std::map<std::string, size_t> series_of_contact;
  for (size_t k = 0; k < steps; ++k) {
    const TreeNode* node = tree.node(path[k]);
    if (node == nullptr || node->event >= events.size()) break;
    const long event = static_cast<long>(node->event);
    const NodeDetails d = node_details(scene, events[node->event]);
    s.nodes.push_back(path[k]);
    s.worst_torque_ratio.points.push_back({double(k), d.worst_torque_ratio, event, worst_joint(d)});
    for (const ContactRow& c : d.contacts) {
      auto [it, added] = series_of_contact.try_emplace(c.name, s.contact_force_z.size());
      if (added) s.contact_force_z.push_back({c.name, {}});
      s.contact_force_z[it->second].points.push_back(
          {double(k), c.force_W.z(), event, c.loaded ? "loaded" : "touching, unloaded"});
    }
  }
  return s;
}

}  // namespace stanceplan::gui
