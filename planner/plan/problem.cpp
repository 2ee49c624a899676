#include "planner/plan/problem.h"

namespace stanceplan {

Stance Problem::stance(const std::vector<StanceContact>& contacts) const {
  std::vector<Contact> list;
  for (const StanceContact& c : contacts) list.push_back(c.contact);
  return Stance(std::move(list));
}

bool Problem::in_initial_stance(const Contact& c) const {
  for (const StanceContact& i : initial_stance)
    if (i.contact.same_surfaces(c)) return true;
  return false;
}

PostureRequest Problem::loaded_request(const std::vector<StanceContact>& contacts,
                                       const Eigen::VectorXd& q) const {
  PostureRequest request;
  for (const StanceContact& c : contacts)
    request.contacts.push_back({c.contact, true, c.placement, std::nullopt, {}});
  request.q_init = q;
  request.q_ref = q;
  return request;
}

}  // namespace stanceplan
