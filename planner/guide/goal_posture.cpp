#include "planner/guide/goal_posture.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <cmath>
#include <vector>

#include "planner/model/kinematics.h"
#include "planner/solver/posture_solver.h"

namespace stanceplan {
namespace {

// A world frame of surface `ref` at the link poses in `data`.
Eigen::Isometry3d surface_pose(const Scene& scene, const std::vector<ModelData>& data,
                               SurfaceRef ref) {
  const Surface& s = scene.surfaces.get(ref);
  return data[size_t(ref.entity)].T_WL[size_t(s.link)] * s.T_LS;
}

// Heading of a direction projected on the ground plane.
double heading(const Eigen::Vector3d& v_W) {
  return std::atan2(v_W.y(), v_W.x());
}

// Where one goal contact pulls entity e: its surface's origin now, where it should be, and the
// change of heading when the contact's placement states one.
struct Pull {
  Eigen::Vector3d from_W, to_W;
  bool turns = false;
  double turn = 0.0;
};

std::vector<Pull> pulls_on(const Problem& problem, const std::vector<ModelData>& data, int e) {
  const Scene& scene = problem.scene;
  std::vector<Pull> pulls;
  for (const StanceContact& g : problem.goal_stance) {
    const bool own1 = g.contact.s1.entity == e, own2 = g.contact.s2.entity == e;
    if (own1 == own2) continue;  // not on e, or a contact within e
    if (!g.placement && problem.in_initial_stance(g.contact)) continue;
    const SurfaceRef own = own1 ? g.contact.s1 : g.contact.s2;
    const SurfaceRef other = own1 ? g.contact.s2 : g.contact.s1;
    const Eigen::Isometry3d T_WO = surface_pose(scene, data, own);
    const Eigen::Isometry3d T_WT = surface_pose(scene, data, other);
    Pull p;
    p.from_W = T_WO.translation();
    if (g.placement && own1) {  // E10-E13: s1's origin at (x, y) of s2's plane, x at theta
      p.to_W = T_WT * Eigen::Vector3d(g.placement->x, g.placement->y, 0.0);
      const Eigen::Vector3d x_W = T_WT.linear() * Eigen::Vector3d(std::cos(g.placement->theta),
                                                                  std::sin(g.placement->theta), 0);
      p.turns = true;
      p.turn = std::remainder(heading(x_W) - heading(T_WO.linear().col(0)), 2.0 * M_PI);
    } else {
      const Eigen::Vector2d c = scene.surfaces.get(other).centroid_S();
      p.to_W = T_WT * Eigen::Vector3d(c.x(), c.y(), 0.0);
    }
    pulls.push_back(p);
  }
  return pulls;
}

// Whether the surface origins span a plane (three or more, not on one line): only then does a
// rotation fitted to them mean anything (a pen's faces all lie along its axis).
bool spread_in_a_plane(const std::vector<Pull>& pulls, const Eigen::Vector3d& from) {
  if (pulls.size() < 3) return false;
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (const Pull& p : pulls) C += (p.from_W - from) * (p.from_W - from).transpose();
  const Eigen::Vector3d l = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(C).eigenvalues();
  return l[1] > 0.01 * l[2];  // ascending: the second largest spread is not negligible
}

// An object held at three or more new contacts may have to turn (a ball turned over in the hand):
// the rotation that best carries the surface origins onto their targets about their centroids
// (Kabsch: the SVD of their cross-covariance), a proper rotation.
Eigen::Matrix3d fitted_rotation(const std::vector<Pull>& pulls, const Eigen::Vector3d& from,
                                const Eigen::Vector3d& to) {
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  for (const Pull& p : pulls) H += (p.from_W - from) * (p.to_W - to).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  D(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1.0 : 1.0;
  return svd.matrixV() * D * svd.matrixU().transpose();
}

}  // namespace

Eigen::VectorXd carried_configuration(const Problem& problem) {
  const System& system = problem.scene.system;
  const std::vector<ModelData> data = system_kinematics(system, problem.initial_configuration);
  Eigen::VectorXd q = problem.initial_configuration;
  for (int e = 0; e < system.num_entities(); ++e) {
    if (!system.entity(e).floating()) continue;
    const std::vector<Pull> pulls = pulls_on(problem, data, e);
    if (pulls.empty()) continue;
    Eigen::Vector3d from = Eigen::Vector3d::Zero(), to = Eigen::Vector3d::Zero();
    double s = 0.0, c = 0.0;
    for (const Pull& p : pulls) {
      from += p.from_W / double(pulls.size());
      to += p.to_W / double(pulls.size());
      if (p.turns) s += std::sin(p.turn), c += std::cos(p.turn);
    }
    const double turn = (s == 0.0 && c == 0.0) ? 0.0 : std::atan2(s, c);
    Eigen::Matrix3d R = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    if (system.entity(e).kind == EntityKind::Object && spread_in_a_plane(pulls, from))
      R = fitted_rotation(pulls, from, to);
    const int o = system.offset(e);
    q.segment<3>(o + Entity::kBasePosition) =
        to + R * (q.segment<3>(o + Entity::kBasePosition) - from);
    const Eigen::Vector4d wxyz = q.segment<4>(o + Entity::kBaseQuaternion);
    const Eigen::Quaterniond turned =
        Eigen::Quaterniond(R) * Eigen::Quaterniond(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
    q.segment<4>(o + Entity::kBaseQuaternion) =
        Eigen::Vector4d(turned.w(), turned.x(), turned.y(), turned.z());
  }
  return q;
}

PostureResult solve_goal_posture(const Problem& problem) {
  SolverOptions options = problem.solver;
  options.diagnose_infeasibility = true;
  const PostureSolver solver(problem.scene, options);
  return solver.solve(problem.loaded_request(problem.goal_stance, carried_configuration(problem)));
}

}  // namespace stanceplan
