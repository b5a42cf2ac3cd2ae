#pragma once

#include <cstdint>
#include <string>

#include <collido/query.h>

namespace collido {

/// The shape kinds a backend builds; values are CollidoShapeKind bits.
enum class ShapeKind : std::uint32_t {
  kTriangleMesh = 1u << 0,
};

/// What a backend instance can do. The runner skips, and reports as skipped, everything else.
struct Capabilities {
  std::uint32_t shape_kinds = 0;        ///< ShapeKind bits
  QueryKindSet queries;                 ///< the questions it answers
  bool update = false;                  ///< update() accepts new vertex positions
  bool counts_bv_tests = false;         ///< results carry bounding-volume test counts
  bool counts_primitive_tests = false;  ///< results carry primitive test counts
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
};

}  // namespace collido
