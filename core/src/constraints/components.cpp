#include "components.h"

#include <algorithm>
#include <map>
#include <numeric>

namespace collido::constraints::detail {
namespace {

/// Union–find over parameter owners (bodies, then variables), with path halving.
class DisjointSets {
 public:
  explicit DisjointSets(int size) : parent_(size) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int item) {
    while (parent_[item] != item) {
      parent_[item] = parent_[parent_[item]];
      item = parent_[item];
    }
    return item;
  }
  void join(int a, int b) { parent_[find(a)] = find(b); }

 private:
  std::vector<int> parent_;
};

void addBody(std::vector<int>& bodies, int body) {
  if (body != kWorld && std::find(bodies.begin(), bodies.end(), body) == bodies.end()) {
    bodies.push_back(body);
  }
}

}  // namespace

ConstraintSupport supportOf(const Constraint& c) {
  ConstraintSupport support;
  // Each kind reads its own references; the others keep their defaults and do not count.
  const bool uses_points =
      !(c.kind == ConstraintKind::kAngle || c.kind == ConstraintKind::kParallel ||
        c.kind == ConstraintKind::kPerpendicular);
  const bool uses_d = c.kind == ConstraintKind::kAngle || c.kind == ConstraintKind::kParallel ||
                      c.kind == ConstraintKind::kPerpendicular ||
                      c.kind == ConstraintKind::kCoaxial;
  const bool uses_e = c.kind != ConstraintKind::kCoincident &&
                      c.kind != ConstraintKind::kDistance && c.kind != ConstraintKind::kClearance;
  std::vector<int> used;
  if (uses_points) used.insert(used.end(), {c.p.body, c.q.body});
  if (uses_d) used.push_back(c.d.body);
  if (uses_e) used.push_back(c.e.body);
  for (int body : used) {
    if (body == kWorld) {
      support.world = true;
    } else {
      addBody(support.bodies, body);
    }
  }
  if (c.target.variable >= 0) support.variables.push_back(c.target.variable);
  return support;
}

std::vector<Component> findComponents(const Problem& problem, const ParameterLayout& layout,
                                      std::vector<int>& frozen) {
  const int body_count = layout.body_count;
  const int owners = body_count + static_cast<int>(problem.variables().size());
  const auto ownerFree = [&](int owner) {
    return owner < body_count ? !problem.bodies()[owner].fixed
                              : !problem.variables()[owner - body_count].fixed;
  };
  DisjointSets sets(owners);
  std::vector<std::vector<int>> free_owners(problem.constraints().size());
  for (int c = 0; c < static_cast<int>(problem.constraints().size()); ++c) {
    const ConstraintSupport support = supportOf(problem.constraints()[c]);
    // References all on one body: moving it moves them together, so the constraint holds or
    // fails whatever the solve does, like one on fixed objects.
    if (support.bodies.size() == 1 && !support.world && support.variables.empty()) continue;
    // A body that may not turn takes no part in a constraint on directions alone.
    const ConstraintKind kind = problem.constraints()[c].kind;
    const bool directions_only = kind == ConstraintKind::kAngle ||
                                 kind == ConstraintKind::kParallel ||
                                 kind == ConstraintKind::kPerpendicular;
    for (int body : support.bodies) {
      if (ownerFree(body) && !(directions_only && problem.bodies()[body].rotation_fixed)) {
        free_owners[c].push_back(body);
      }
    }
    for (int variable : support.variables) {
      if (ownerFree(body_count + variable)) free_owners[c].push_back(body_count + variable);
    }
    for (std::size_t k = 1; k < free_owners[c].size(); ++k) {
      sets.join(free_owners[c][0], free_owners[c][k]);
    }
  }
  std::map<int, int> component_of_root;
  std::vector<Component> components;
  std::vector<bool> owner_listed(owners, false);
  for (int c = 0; c < static_cast<int>(problem.constraints().size()); ++c) {
    if (free_owners[c].empty()) {
      frozen.push_back(c);
      continue;
    }
    const int root = sets.find(free_owners[c][0]);
    auto [it, inserted] = component_of_root.emplace(root, static_cast<int>(components.size()));
    if (inserted) components.emplace_back();
    Component& component = components[it->second];
    component.constraints.push_back(c);
    for (int owner : free_owners[c]) {
      if (owner_listed[owner]) continue;
      owner_listed[owner] = true;
      if (owner < body_count) {
        component.bodies.push_back(owner);
        for (int k = 0; k < 6; ++k) {
          if (layout.free[layout.bodyColumn(owner) + k])
            component.columns.push_back(layout.bodyColumn(owner) + k);
        }
      } else {
        component.columns.push_back(layout.variableColumn(owner - body_count));
      }
    }
  }
  for (Component& component : components) {
    std::sort(component.columns.begin(), component.columns.end());
  }
  return components;
}

}  // namespace collido::constraints::detail
