#pragma once
// Collision geometry of a System for collision avoidance (docs/METHOD.md section 4, E20), split the
// model/data way: CollisionModel is const (FCL shapes, links, candidate pairs) and can be shared by
// threads; CollisionData is one thread's mutable workspace (world pose of every shape, Jacobian
// scratch). Meshes become convex hulls (fcl::Convexd): signed distance is wrong on fcl::BVHModel
// (docs/DEPENDENCIES.md section 2), and the paper itself uses convex bounding volumes.
#include <Eigen/Geometry>
#include <array>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "planner/collision/collision_matrix.h"
#include "planner/collision/convex_hull.h"
#include "planner/collision/polytope_penetration.h"
#include "planner/model/model_data.h"
#include "planner/model/system.h"

namespace fcl {
template <typename S>
class CollisionGeometry;
template <typename S>
class Convex;
}  // namespace fcl

namespace stanceplan {

// The convex hull of one mesh file at one scale, shared by every link that uses it.
struct MeshHull {
  std::shared_ptr<const ConvexHull> hull;
  std::shared_ptr<const ConvexPolytope> polytope;
  std::shared_ptr<fcl::Convex<double>> convex;
};

// Hulls by (resolved mesh path, scale): each mesh file is loaded and hulled once. Thread-safe; may
// be shared by several CollisionModels (e.g. one per scenario of a benchmark run).
class HullCache {
 public:
  // Throws InputError naming the file when it cannot be read or has no 3-D hull.
  MeshHull get(const std::string& mesh_path, const Eigen::Vector3d& scale,
               const ConvexHullOptions& options = {});
  size_t size() const;

 private:
  mutable std::mutex mutex_;
  std::map<std::pair<std::string, std::array<double, 3>>, MeshHull> hulls_;
};

// One collision shape fixed to a link, stored as a convex core grown by a margin (the core's
// Minkowski sum with a ball): a sphere is a point core with margin = radius; boxes and cylinders
// (circumscribed prisms) are polytope cores with margin 0; a mesh is its (simplified) convex hull
// with margin = the hull's max_outside_distance, so that it contains every mesh vertex. Only
// polytopes and points ever reach FCL, and only for GJK (separated cores): on curved support
// functions GJK/EPA converge slowly (too noisy for finite differences), and FCL 0.7's EPA aborts
// the process on nearly parallel faces (see polytope_penetration.h), so overlapping cores go
// through our own exact separating-axis test instead.
struct CollisionShape {
  ShapeType type = ShapeType::Box;                           // what the URDF declared
  std::shared_ptr<fcl::CollisionGeometry<double>> geometry;  // core: Boxd, Convexd, or Sphered(0)
  bool point_core = false;                                   // sphere: the core is its centre
  double margin = 0.0;  // sphere radius; mesh hull's max_outside_distance; else 0
  std::shared_ptr<const ConvexPolytope> polytope;          // the core (not for point cores)
  std::shared_ptr<const ConvexHull> hull;                  // meshes and cylinders
  Eigen::Isometry3d T_LG = Eigen::Isometry3d::Identity();  // shape frame in the link frame
};

// A link that has collision geometry.
struct CollisionLink {
  int entity = -1;
  int link = -1;        // index into the entity's Model::links
  int first_shape = 0;  // its shapes are shapes()[first_shape, first_shape + num_shapes)
  int num_shapes = 0;
  bool moves = true;  // false when its pose never depends on q (environment, fixed base)
  // Bounding sphere of all its shapes, in the link frame.
  Eigen::Vector3d center_L = Eigen::Vector3d::Zero();
  double radius = 0.0;
  // Bounding box of all its shapes, axis-aligned in the link frame: centre and half extents. Far
  // tighter than the sphere for a long or flat link (a platform, a floor, a shin).
  Eigen::Vector3d box_center_L = Eigen::Vector3d::Zero();
  Eigen::Vector3d box_half_L = Eigen::Vector3d::Zero();
};

// A candidate pair: indices into CollisionModel::links(), a < b.
struct CollisionPair {
  int a = -1;
  int b = -1;
};

// A pair of links with collision geometry that is never checked, and why: "rigidly connected"
// (only fixed joints between them), "adjacent bodies" (one movable joint between their rigid
// bodies), "static" (neither moves), "SRDF (<reason>)", "computed (<reason>)" (a computed
// self-collision matrix, collision_matrix.h), or "disabled" (CollisionOptions). Pairs
// joined directly by one joint (Model::adjacent) are left out, as docs/PLAN_FORMAT.md's
// collision_pairs_ignored expects.
struct ExcludedPair {
  int entity_a = -1;
  int link_a = -1;  // index into the entity's Model::links
  int entity_b = -1;
  int link_b = -1;
  std::string reason;
};

// A link named by its entity's name and its own name.
struct LinkName {
  std::string entity;
  std::string link;
};

struct CollisionOptions {
  // SRDF files whose <disable_collisions> pairs apply to one entity: (entity name, SRDF path).
  // Links the entity's model lacks are skipped (an SRDF may describe a fuller model); they are
  // counted in CollisionModel::num_unknown_srdf_links().
  std::vector<std::pair<std::string, std::string>> srdf_files;
  // Further pairs that are never checked, possibly across entities. Unknown names throw.
  std::vector<std::pair<LinkName, LinkName>> disabled_pairs;
  // When set, every entity but the environment whose SRDF files disable no pair of its own links
  // (or which has none) gets its self-collision matrix computed with these options
  // (collision_matrix.h), and the pairs it disables by sampling are never checked. Off here; the
  // scene builder turns it on.
  std::optional<CollisionMatrixOptions> computed_matrix;
  // Mesh hulls are simplified by 1 mm (qhull W, see ConvexHullOptions) and grown by their
  // max_outside_distance, so that every shape still contains its whole mesh. On TALOS this cuts
  // the hulls from 231 to 98 vertices on average (953 to 382 at most) for margins up to 1.1 mm.
  ConvexHullOptions hull = {.degenerate_thickness = 1e-4, .simplify_tolerance = 1e-3};
  // Cylinders become prisms with this many sides, circumscribed (they contain the cylinder; the
  // radial excess is radius * (1 / cos(pi / sides) - 1), 0.5 % at 32 sides).
  int cylinder_sides = 32;
};

class CollisionModel {
 public:
  // Builds shapes for every collision geometry of every link of every entity, then the candidate
  // pairs (E20: every pair of links "not joined by a joint") minus
  //  - links of one entity that are rigidly connected (only fixed joints between them),
  //  - links of one entity joined by one movable joint, counting rigidly connected links as one
  //    body (this includes Model::adjacent),
  //  - pairs of links that never move (both in the environment, or on a fixed robot's base body):
  //    their distance is a constant,
  //  - pairs disabled by an SRDF file, by a computed self-collision matrix
  //    (options.computed_matrix) or by options.disabled_pairs.
  // `cache` (optional) shares hulls with other models. Throws InputError on an unreadable mesh,
  // SRDF, or unknown entity/link name in options.disabled_pairs.
  CollisionModel(const System& system, const CollisionOptions& options = {},
                 HullCache* cache = nullptr);

  const std::vector<CollisionShape>& shapes() const { return shapes_; }
  const std::vector<CollisionLink>& links() const { return links_; }
  const std::vector<CollisionPair>& pairs() const { return pairs_; }
  int num_entities() const { return static_cast<int>(first_link_.size()); }

  // Index into links() of (entity, link), or -1 when that link has no collision geometry.
  int find_link(int entity, int link) const;
  // Index into pairs() of the candidate pair of two links (any order), or -1 when not a candidate.
  int find_pair(int entity_a, int link_a, int entity_b, int link_b) const;

  const std::vector<ExcludedPair>& excluded_pairs() const { return excluded_; }
  // Pairs that only an SRDF file excludes.
  int num_srdf_disabled_pairs() const { return num_srdf_disabled_; }
  int num_unknown_srdf_links() const { return num_unknown_srdf_links_; }
  // The self-collision matrices computed for options.computed_matrix, one per entity that got one,
  // and the pairs that only they exclude.
  struct ComputedMatrix {
    int entity = -1;
    CollisionMatrix matrix;
  };
  const std::vector<ComputedMatrix>& computed_matrices() const { return computed_matrices_; }
  int num_computed_disabled_pairs() const { return num_computed_disabled_; }

 private:
  void add_entity_shapes(const System& system, int entity, const CollisionOptions& options,
                         HullCache& cache);
  void build_pairs(const System& system, const CollisionOptions& options, HullCache& cache);
  void compute_matrices(const System& system, const CollisionMatrixOptions& options,
                        const std::vector<bool>& srdf_disables, HullCache& cache,
                        const std::function<void(int, int, const std::string&)>& mark);

  std::vector<CollisionShape> shapes_;
  std::vector<CollisionLink> links_;
  std::vector<CollisionPair> pairs_;
  std::vector<ExcludedPair> excluded_;
  std::vector<int> first_link_;  // per entity: index into link_of_ of its link 0
  std::vector<int> link_of_;     // (entity, link) flattened -> index into links_, or -1
  std::vector<int> pair_of_;     // links_.size()^2 -> index into pairs_, or -1
  int num_srdf_disabled_ = 0;
  int num_unknown_srdf_links_ = 0;
  std::vector<ComputedMatrix> computed_matrices_;
  int num_computed_disabled_ = 0;
};

// One thread's workspace: the world pose of every shape, and scratch for penetration depths and
// gradients.
class CollisionData {
 public:
  CollisionData(const System& system, const CollisionModel& model);

  // T_WG of every shape from each entity's link poses (ModelData::T_WL after forward_kinematics);
  // data[e] belongs to entity e. Allocates nothing.
  void update(const CollisionModel& model, std::span<const ModelData> data);

  std::vector<Eigen::Isometry3d> T_WG;  // per shape of CollisionModel::shapes()
  Eigen::MatrixXd J_scratch;            // 3 x (largest entity nq)
  PenetrationScratch penetration;       // reserved for the model's largest polytope
};

}  // namespace stanceplan
