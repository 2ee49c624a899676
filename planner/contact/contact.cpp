#include "planner/contact/contact.h"

#include <algorithm>

namespace stanceplan {

Stance::Stance(std::vector<Contact> contacts) : contacts_(std::move(contacts)) {
  std::sort(contacts_.begin(), contacts_.end());
}

bool Stance::uses_surface(SurfaceRef ref) const {
  return std::any_of(contacts_.begin(), contacts_.end(),
                     [&](const Contact& c) { return c.s1 == ref || c.s2 == ref; });
}

int Stance::find(const Contact& c) const {
  for (int i = 0; i < size(); ++i)
    if (contacts_[i].same_surfaces(c)) return i;
  return -1;
}

int stance_difference(const Stance& a, const Stance& b) {
  int d = 0;
  for (const Contact& c : a.contacts()) d += b.find(c) < 0;
  for (const Contact& c : b.contacts()) d += a.find(c) < 0;
  return d;
}

Stance Stance::with(const Contact& c) const {
  std::vector<Contact> next = contacts_;
  next.push_back(c);
  return Stance(std::move(next));
}

Stance Stance::without(int index) const {
  std::vector<Contact> next = contacts_;
  next.erase(next.begin() + index);
  return Stance(std::move(next));
}

size_t Stance::hash() const {
  size_t h = 0x9e3779b97f4a7c15ull;
  for (const Contact& c : contacts_)
    for (int v : {c.s1.entity, c.s1.index, c.s2.entity, c.s2.index, int(c.bilateral), int(c.fixed)})
      h ^= std::hash<int>()(v) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  return h;
}

}  // namespace stanceplan
