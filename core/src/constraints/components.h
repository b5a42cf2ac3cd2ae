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
};
ConstraintSupport supportOf(const Constraint& constraint);

/// Splits the constraint graph into connected components over free parameters. Constraints that
/// touch no free parameter are returned in `frozen` (they hold or they do not; nothing moves).
std::vector<Component> findComponents(const Problem& problem, const ParameterLayout& layout,
                                      std::vector<int>& frozen);

}  // namespace collido::constraints::detail
