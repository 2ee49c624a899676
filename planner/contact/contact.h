#pragma once
// Contacts and stances (docs/METHOD.md section 2). A contact joins surface s1 (the smaller one:
// forces act at its vertices) and s2, on different links. A stance is a set of contacts in which
// every surface appears at most once, kept sorted so that equal stances compare and hash equal.
#include <cstddef>
#include <optional>
#include <vector>

#include "planner/contact/surface_set.h"

namespace stanceplan {

struct Contact {
  SurfaceRef s1;
  SurfaceRef s2;
  bool bilateral = false;  // force free in R^3 (no unilaterality, no friction cone)
  bool fixed = false;      // never removed by the search

  // The search's equivalence class: the same pair of surfaces (docs/METHOD.md section 2).
  bool same_surfaces(const Contact& other) const { return s1 == other.s1 && s2 == other.s2; }
  bool operator==(const Contact& other) const = default;
  auto operator<=>(const Contact& other) const = default;
};

// Relative placement of s1 in s2's frame (E10-E13): s1's origin at (x, y) in s2's plane, s1's x
// axis at angle theta from s2's x axis.
struct Placement {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;
};

// A contact touched at some configuration, and whether it carries force there (a plan step's
// "contacts", a search event's candidate).
struct PlanContact {
  Contact contact;
  bool loaded = true;
};

class Stance {
 public:
  Stance() = default;
  explicit Stance(std::vector<Contact> contacts);  // sorts; see valid() for the rules

  const std::vector<Contact>& contacts() const { return contacts_; }
  int size() const { return static_cast<int>(contacts_.size()); }
  bool empty() const { return contacts_.empty(); }
  bool uses_surface(SurfaceRef ref) const;
  // Index of the contact joining the same surfaces as c, or -1.
  int find(const Contact& c) const;
  Stance with(const Contact& c) const;  // adds c
  Stance without(int index) const;      // removes contacts()[index]
  bool operator==(const Stance& other) const = default;
  size_t hash() const;

 private:
  std::vector<Contact> contacts_;
};

// How many contacts one stance has that the other has not (same surface pairs), both ways: 0 for
// the same stance, 1 between a stance and one with a contact more.
int stance_difference(const Stance& a, const Stance& b);

struct StanceHash {
  size_t operator()(const Stance& s) const { return s.hash(); }
};

}  // namespace stanceplan
