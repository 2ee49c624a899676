#pragma once
// What the search tells its observers (the snapshot writer, the GUI, the progress line), and the
// step gate through which an observer can hold the search between events. The planner knows
// nothing of windows or images: observers are plain callbacks.
#include <Eigen/Core>
#include <condition_variable>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "planner/contact/contact.h"
#include "planner/solver/posture_request.h"
#include "planner/solver/posture_result.h"

namespace stanceplan {

// MotionFailed: a transition of a plan found has no motion (lazy validation, stance_search.h);
// its node (and subtree) is dropped and the search goes on.
enum class SearchEventKind { Expansion, Candidate, Milestone, PlanFound, Failure, MotionFailed };
const char* to_string(SearchEventKind kind);

enum class CandidateCase { None, Add, Remove };  // docs/METHOD.md case 1 / case 2

struct SearchEvent {
  int number = 0;  // 0, 1, 2, ... in the order the search publishes them
  SearchEventKind kind = SearchEventKind::Expansion;
  int node = -1;    // the node expanded, created, reaching the milestone, or the goal node
  int parent = -1;  // candidates: the node being expanded
  Stance stance;    // the node's stance, or the candidate's target stance
  CandidateCase candidate_case = CandidateCase::None;
  Contact changed;                               // candidates: the contact added or removed
  PostureStatus status = PostureStatus::Solved;  // candidates
  std::string message;    // candidates: why rejected; failure, motion failed: why; milestone:
                          // why skipped (empty when a node reached it)
  bool accepted = false;  // candidates: a new node was made
  Eigen::VectorXd q;      // the configuration (candidates: the solver's final iterate)
  std::vector<PlanContact> contacts;  // touched at q, with which carry force
  std::vector<VertexForce> forces;    // VertexForce::contact indexes `contacts`
  double time_ms = 0.0;               // candidates: solver time
  // Candidates and expansions: the solve's figures, for inspection (the GUI's node view).
  int iterations = 0;
  std::vector<Eigen::VectorXd> torques;     // per entity (empty for entities without dofs)
  std::map<std::string, double> residuals;  // candidates: worst violation per family
  // Candidates: the solve's request, to solve it again alone (stanceplan plan --requests, then
  // stanceplan replay).
  std::shared_ptr<const PostureRequest> request;
  int milestone = 0;  // the milestone index targeted after this event
  int nodes = 0;      // tree size after this event
};

// A Milestone event that no node reached: the search skipped it (its message says why,
// SearchOptions::skip_unreached_milestones; its node is the one nearest to it).
inline bool skipped_milestone(const SearchEvent& e) {
  return e.kind == SearchEventKind::Milestone && !e.message.empty();
}

using SearchObserver = std::function<void(const SearchEvent&)>;

// Holds the search between events while paused. The search calls pass() before publishing each
// event; pause() / step(n) / resume() come from any other thread. cancel() releases a waiting
// search.
class StepGate {
 public:
  void pause();
  void resume();
  void step(int events = 1);  // let `events` more events through, then pause again
  void cancel();
  void reopen();  // lifts a cancel() for a new search; the pause state stays
  bool paused() const;
  // Blocks while paused (unless cancelled); returns false once cancelled.
  bool pass();

 private:
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  bool paused_ = false;
  bool cancelled_ = false;
  int budget_ = 0;
};

}  // namespace stanceplan
