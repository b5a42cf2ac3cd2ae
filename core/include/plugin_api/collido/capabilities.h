#pragma once

#include <cstdint>
#include <string>

#include <collido/query.h>

namespace collido {

/// The shape kinds a backend builds; values are CollidoShapeKind bits.
enum class ShapeKind : std::uint32_t {
  kTriangleMesh = 1u << 0,
  kNurbsSurface = 1u << 1,
};

/// What a backend instance can do. The runner skips, and reports as skipped, everything else.
struct Capabilities {
  std::uint32_t shape_kinds = 0;        ///< ShapeKind bits
  QueryKindSet queries;                 ///< the questions it answers
  bool update = false;                  ///< update() accepts new vertex positions
  bool counts_bv_tests = false;         ///< results carry bounding-volume test counts
  bool counts_primitive_tests = false;  ///< results carry primitive test counts
  bool counts_update_work = false;      ///< update() reports the volumes it refit and rebuilt
  std::uint64_t max_contacts = 0;       ///< most contacts a query can return; 0 = no limit
  std::string notes;                    ///< limits worth knowing, for people

  bool buildsShape(ShapeKind kind) const {
    return (shape_kinds & static_cast<std::uint32_t>(kind)) != 0;
  }
};

/// What a scene will ask of one model, so that build() computes only that.
struct BuildNeeds {
  QueryKindSet queries;  ///< the questions the model will be part of
  bool deforms = false;  ///< update() will be called; rigid models skip refit bookkeeping
  /// The kinds asked anywhere among the objects linked to this one through queries (directly or
  /// through others), a superset of `queries`; empty when the host did not say. A backend whose
  /// model type depends on the kinds picks it by this set, so both models of every pair it will
  /// be asked about are of one type.
  QueryKindSet linked_queries{};
};

class BackendModel;

/// Another active state of the same object, given to build() so the backend may share with it
/// what does not depend on vertex positions: the same vertex count and triangle list (checked
/// by the adapter). It is alive during the call; the new model must not rely on it afterwards.
struct StateSibling {
  const BackendModel* model = nullptr;  ///< null: the model is built on its own
};

/// Work one update() did; the figures are meaningful only when `counted`.
struct UpdateCounters {
  std::uint64_t nodes_refit = 0;    ///< bounding volumes measured anew, the structure kept
  std::uint64_t rebuilds = 0;       ///< structures rebuilt from scratch (models or subtrees)
  std::uint64_t nodes_rebuilt = 0;  ///< bounding volumes in those rebuilt structures
  bool counted = false;
};

}  // namespace collido
