// Solves in worker processes: the wire format round-trips, results are bitwise those of the
// calling process, and a worker that dies is replaced.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include <cstring>
#include <thread>

#include "planner/solver/solver_pool.h"
#include "planner/solver/solver_wire.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

class Pool : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { scene_ = new Scene(test::humanoid_scene("flat_ground")); }
  static void TearDownTestSuite() { delete scene_; }
  // Standing from six different guesses, one with force guesses, one with a fixed placement and
  // one unloaded contact.
  static std::vector<PostureRequest> requests() {
    std::vector<PostureRequest> out;
    for (int i = 0; i < 6; ++i) {
      PostureRequest r;
      r.contacts = {test::task(*scene_, "robot/l_sole", "env/floor"),
                    test::task(*scene_, "robot/r_sole", "env/floor")};
      if (i >= 4) r.contacts[0].placement = Placement{-1.49, 0.085, 0.0};
      if (i == 5) {  // case 2: both soles placed, the right one about to leave
        r.contacts[1].placement = Placement{-1.49, -0.085, 0.0};
        r.contacts[1].loaded = false;
      }
      if (i == 3)  // warm-started forces at the four vertices of either sole
        for (ContactTask& t : r.contacts)
          t.force_guess_W.assign(4, Eigen::Vector3d(0.5, -0.2, 40.0));
      if (i == 2) r.progress_budget = 30;  // a candidate's solve: stopped when it stalls
      if (i == 1) r.approaching = {test::task(*scene_, "robot/r_sole", "env/floor").contact};
      r.q_init = test::standing_configuration(*scene_);
      r.q_init[0] = 0.01 * i;
      out.push_back(r);
    }
    return out;
  }
  static Scene* scene_;
};
Scene* Pool::scene_ = nullptr;

void expect_identical(const PostureResult& a, const PostureResult& b) {
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.iterations, b.iterations);
  ASSERT_EQ(a.q.size(), b.q.size());
  EXPECT_EQ(0, std::memcmp(a.q.data(), b.q.data(), sizeof(double) * a.q.size()));
  ASSERT_EQ(a.forces.size(), b.forces.size());
  for (size_t i = 0; i < a.forces.size(); ++i) EXPECT_EQ(a.forces[i].force_W, b.forces[i].force_W);
  ASSERT_EQ(a.torques.size(), b.torques.size());
  for (size_t i = 0; i < a.torques.size(); ++i) EXPECT_EQ(a.torques[i], b.torques[i]);
  EXPECT_EQ(a.residuals, b.residuals);
}

TEST_F(Pool, TheWireFormatRoundTrips) {
  const PostureSolver solver(*scene_, SolverOptions{});
  for (const PostureRequest& r : requests()) {
    const PostureRequest back = deserialize_request(serialize(r));
    ASSERT_EQ(back.contacts.size(), r.contacts.size());
    for (size_t i = 0; i < r.contacts.size(); ++i) {
      EXPECT_EQ(back.contacts[i].contact, r.contacts[i].contact);
      EXPECT_EQ(back.contacts[i].loaded, r.contacts[i].loaded);
      EXPECT_EQ(back.contacts[i].placement.has_value(), r.contacts[i].placement.has_value());
      EXPECT_EQ(back.contacts[i].force_guess_W, r.contacts[i].force_guess_W);
    }
    EXPECT_EQ(back.q_init, r.q_init);
    EXPECT_EQ(back.progress_budget, r.progress_budget);
    EXPECT_EQ(back.approaching, r.approaching);
    const PostureResult result = solver.solve(r);
    const PostureResult again = deserialize_result(serialize(result));
    expect_identical(result, again);
    EXPECT_EQ(again.message, result.message);
    EXPECT_EQ(again.time_ms, result.time_ms);
  }
}

TEST_F(Pool, TwoWorkerProcessesGiveTheResultsOfTheCallingProcess) {
  const PostureSolver solver(*scene_, SolverOptions{});
  const auto reqs = requests();
  SolverPool pool(solver, 2);
  ASSERT_EQ(pool.processes(), 2);
  const std::vector<PostureResult> parallel = pool.solve_all(reqs);
  ASSERT_EQ(parallel.size(), reqs.size());
  for (size_t i = 0; i < reqs.size(); ++i) {
    EXPECT_EQ(parallel[i].status, PostureStatus::Solved) << i << " " << parallel[i].message;
    expect_identical(solver.solve(reqs[i]), parallel[i]);
  }
}

TEST_F(Pool, AWorkerThatDiesIsReplaced) {
  const PostureSolver solver(*scene_, SolverOptions{});
  SolverPool pool(solver, 2);
  const pid_t victim = pool.worker_pids()[0];
  ASSERT_GT(victim, 0);
  ASSERT_EQ(kill(victim, SIGKILL), 0);
  waitpid(victim, nullptr, 0);
  const std::vector<PostureResult> results = pool.solve_all(requests());
  for (const PostureResult& r : results) EXPECT_EQ(r.status, PostureStatus::Solved) << r.message;
  EXPECT_NE(pool.worker_pids()[0], victim);
}

TEST_F(Pool, MalformedRequestsThrowInTheCallingProcess) {
  const PostureSolver solver(*scene_, SolverOptions{});
  SolverPool pool(solver, 2);
  auto reqs = requests();
  reqs[3].q_init.resize(3);
  EXPECT_THROW(pool.solve_all(reqs), std::invalid_argument);
}

// Bytes from a file (planner/io/request_file.h) may be anything: a count that the bytes left
// cannot hold is a truncated message, never an allocation of that size.
TEST(WireFormat, ACountLargerThanTheBytesLeftIsATruncatedMessage) {
  PostureRequest request;
  request.q_init = Eigen::VectorXd::Zero(3);
  std::string bytes = serialize(request);
  // The first vector (q_init) follows the contact and approaching counts: find its count, 3.
  const uint64_t three = 3, huge = uint64_t(1) << 60;
  const size_t at = bytes.find(std::string(reinterpret_cast<const char*>(&three), 8));
  ASSERT_NE(at, std::string::npos);
  bytes.replace(at, 8, std::string(reinterpret_cast<const char*>(&huge), 8));
  try {
    deserialize_request(bytes);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "solver pool: truncated message");
  }
}

}  // namespace
}  // namespace stanceplan
