#include "planner/solver/solver_wire.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace stanceplan {
namespace {

// --- a minimal binary encoding (same binary on both ends: no byte-order concerns)
class Writer {
 public:
  template <class T>
  void pod(const T& v) {
    bytes.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  void text(const std::string& s) {
    pod<uint64_t>(s.size());
    bytes.append(s);
  }
  void vector(const Eigen::VectorXd& v) {
    pod<uint64_t>(v.size());
    bytes.append(reinterpret_cast<const char*>(v.data()), sizeof(double) * v.size());
  }
  void vec3(const Eigen::Vector3d& v) {
    for (int i = 0; i < 3; ++i) pod(v[i]);
  }
  void contact(const Contact& c) {
    for (int v : {c.s1.entity, c.s1.index, c.s2.entity, c.s2.index}) pod<int32_t>(v);
    pod<uint8_t>(c.bilateral);
    pod<uint8_t>(c.fixed);
  }
  void placement(const std::optional<Placement>& p) {
    pod<uint8_t>(p.has_value());
    if (p) {
      pod(p->x);
      pod(p->y);
      pod(p->theta);
    }
  }
  std::string bytes;
};

class Reader {
 public:
  explicit Reader(const std::string& b) : bytes_(b) {}
  template <class T>
  T pod() {
    if (at_ + sizeof(T) > bytes_.size()) throw std::runtime_error("solver pool: truncated message");
    T v;
    std::memcpy(&v, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  std::string text() {
    const auto n = pod<uint64_t>();
    if (n > bytes_.size() - at_) throw std::runtime_error("solver pool: truncated message");
    std::string s = bytes_.substr(at_, n);
    at_ += n;
    return s;
  }
  Eigen::VectorXd vector() {
    const auto n = pod<uint64_t>();
    // A count the bytes left cannot hold is a malformed message (a file cut short or from another
    // build: planner/io/request_file.h), not an allocation to try.
    if (n > (bytes_.size() - at_) / sizeof(double))
      throw std::runtime_error("solver pool: truncated message");
    Eigen::VectorXd v(n);
    for (uint64_t i = 0; i < n; ++i) v[i] = pod<double>();
    return v;
  }
  Eigen::Vector3d vec3() {
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i) v[i] = pod<double>();
    return v;
  }
  Contact contact() {
    Contact c;
    c.s1.entity = pod<int32_t>();
    c.s1.index = pod<int32_t>();
    c.s2.entity = pod<int32_t>();
    c.s2.index = pod<int32_t>();
    c.bilateral = pod<uint8_t>();
    c.fixed = pod<uint8_t>();
    return c;
  }
  std::optional<Placement> placement() {
    if (!pod<uint8_t>()) return std::nullopt;
    Placement p;
    p.x = pod<double>();
    p.y = pod<double>();
    p.theta = pod<double>();
    return p;
  }

 private:
  const std::string& bytes_;
  size_t at_ = 0;
};

}  // namespace

std::string serialize(const PostureRequest& request) {
  Writer w;
  w.pod<uint64_t>(request.contacts.size());
  for (const ContactTask& t : request.contacts) {
    w.contact(t.contact);
    w.pod<uint8_t>(t.loaded);
    w.placement(t.placement);
    w.placement(t.placement_target);
    w.pod<double>(t.standoff);
    w.pod<uint64_t>(t.force_guess_W.size());
    for (const Eigen::Vector3d& f : t.force_guess_W) w.vec3(f);
  }
  w.vector(request.q_init);
  w.vector(request.q_ref);
  w.pod<int32_t>(request.progress_budget);
  w.pod<uint64_t>(request.approaching.size());
  for (const Contact& c : request.approaching) w.contact(c);
  return w.bytes;
}

PostureRequest deserialize_request(const std::string& bytes) {
  Reader r(bytes);
  PostureRequest request;
  const auto n = r.pod<uint64_t>();
  for (uint64_t i = 0; i < n; ++i) {
    ContactTask t;
    t.contact = r.contact();
    t.loaded = r.pod<uint8_t>();
    t.placement = r.placement();
    t.placement_target = r.placement();
    t.standoff = r.pod<double>();
    const auto guesses = r.pod<uint64_t>();
    for (uint64_t k = 0; k < guesses; ++k) t.force_guess_W.push_back(r.vec3());
    request.contacts.push_back(t);
  }
  request.q_init = r.vector();
  request.q_ref = r.vector();
  request.progress_budget = r.pod<int32_t>();
  const auto approaching = r.pod<uint64_t>();
  for (uint64_t i = 0; i < approaching; ++i) request.approaching.push_back(r.contact());
  return request;
}

std::string serialize(const PostureResult& result) {
  Writer w;
  w.pod<int32_t>(static_cast<int32_t>(result.status));
  w.text(result.message);
  w.vector(result.q);
  w.pod<uint64_t>(result.forces.size());
  for (const VertexForce& f : result.forces) {
    w.pod<int32_t>(f.contact);
    w.pod<int32_t>(f.vertex);
    w.vec3(f.point_W);
    w.vec3(f.force_W);
  }
  w.pod<uint64_t>(result.torques.size());
  for (const Eigen::VectorXd& t : result.torques) w.vector(t);
  w.pod<uint64_t>(result.placements.size());
  for (const Placement& p : result.placements) w.placement(p);
  w.pod<int32_t>(result.iterations);
  w.pod(result.time_ms);
  w.pod(result.objective);
  w.pod<uint64_t>(result.residuals.size());
  for (const auto& [family, value] : result.residuals) {
    w.text(family);
    w.pod(value);
  }
  w.pod<uint64_t>(result.residual_contacts.size());
  for (const auto& [family, contact] : result.residual_contacts) {
    w.text(family);
    w.pod<int32_t>(contact);
  }
  w.text(result.blocking_family);
  return w.bytes;
}

PostureResult deserialize_result(const std::string& bytes) {
  Reader r(bytes);
  PostureResult result;
  result.status = static_cast<PostureStatus>(r.pod<int32_t>());
  result.message = r.text();
  result.q = r.vector();
  const auto forces = r.pod<uint64_t>();
  for (uint64_t i = 0; i < forces; ++i) {
    VertexForce f;
    f.contact = r.pod<int32_t>();
    f.vertex = r.pod<int32_t>();
    f.point_W = r.vec3();
    f.force_W = r.vec3();
    result.forces.push_back(f);
  }
  const auto torques = r.pod<uint64_t>();
  for (uint64_t i = 0; i < torques; ++i) result.torques.push_back(r.vector());
  const auto placements = r.pod<uint64_t>();
  for (uint64_t i = 0; i < placements; ++i) result.placements.push_back(*r.placement());
  result.iterations = r.pod<int32_t>();
  result.time_ms = r.pod<double>();
  result.objective = r.pod<double>();
  const auto residuals = r.pod<uint64_t>();
  for (uint64_t i = 0; i < residuals; ++i) {
    const std::string family = r.text();
    result.residuals[family] = r.pod<double>();
  }
  const auto residual_contacts = r.pod<uint64_t>();
  for (uint64_t i = 0; i < residual_contacts; ++i) {
    const std::string family = r.text();
    result.residual_contacts[family] = r.pod<int32_t>();
  }
  result.blocking_family = r.text();
  return result;
}

}  // namespace stanceplan
