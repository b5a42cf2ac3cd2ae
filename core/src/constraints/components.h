#pragma once

#include <vector>

#include <collido/constraints/problem.h>

#include "equations.h"

namespace collido::constraints::detail {

/// Constraints that share free parameters, with those parameters: solved apart from the others.
struct Component {
  std::vector<int> constraints;  ///< in the problem's order
  std::vector<int> columns;      ///< free global parameter columns, ascending
  std::vector<int> bodies;       ///< free bodies it moves
};

/// The bodies and variables a constraint refers to (fixed ones included).
struct ConstraintSupport {
  std::vector<int> bodies;
  std::vector<int> variables;
  bool world = false;  ///< some reference is on the world frame
};
ConstraintSupport supportOf(const Constraint& constraint);

/// Splits the constraint graph into connected components over free parameters. Constraints that
/// no change can affect (on fixed objects only, or on one body alone) are returned in `frozen`:
/// they hold or they do not.
std::vector<Component> findComponents(const Problem& problem, const ParameterLayout& layout,
                                      std::vector<int>& frozen);

}  // namespace collido::constraints::detail
