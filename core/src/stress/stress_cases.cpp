// The stress suite's entry point: the category table (name, severities, generator), the per-case
// seeds, and the naming of cases.
#include <collido/stress/stress_cases.h>

#include <array>

#include "stress_generators.h"

namespace collido::stress {
namespace {

struct CategoryInfo {
  Category category;
  const char* name;
  SeverityRange severities;
  std::vector<int> defaults;
  detail::CaseGenerator generate;
};

// Indexed by Category. The meanings are the contract of each generator (and scenes/README.md
// repeats them).
const std::array<CategoryInfo, 10>& table() {
  static const std::array<CategoryInfo, 10> categories = {{
      {Category::kCoplanar,
       "coplanar",
       {0, 3,
        "how the common plane is posed: 0 the plane z = 1 at identity poses; 1 exact 90°/180° "
        "rotations (shared, or one per object); 2 one generic rotation and translation shared by "
        "both (still exactly coplanar for the oracle); 3 B's pose the product of A's and an exact "
        "in-plane motion, rounded"},
       {0, 1, 2, 3},
       &detail::coplanarCase},
      {Category::kTouching,
       "touching",
       {0, 2,
        "how the exactly touching pair is posed: 0 identity poses; 1 exact 90°/180° rotations "
        "(shared, or one per object); 2 one generic rotation and translation shared by both"},
       {0, 1, 2},
       &detail::touchingCase},
      {Category::kNearTouching,
       "near_touching",
       {1, 18,
        "gap exponent: B is 10^-severity (object size 1) above or below exact contact; past 15 "
        "the offset falls below the double grid at the contact and the case becomes touching"},
       {3, 5, 7, 9, 11, 13, 15},
       &detail::nearTouchingCase},
      {Category::kDegenerate,
       "degenerate",
       {0, 15,
        "thinness: 0 exactly degenerate triangles (zero area, collinear or repeated vertices); "
        "s >= 1 slivers and needles 10^-s thin"},
       {0, 3, 6, 9, 12, 15},
       &detail::degenerateCase},
      {Category::kFarFromOrigin,
       "far_from_origin",
       {0, 15, "distance exponent: the pair (size 1) is translated about 10^severity"},
       {3, 4, 5, 6, 7, 8},
       &detail::farFromOriginCase},
      {Category::kScaled,
       "scaled",
       {-15, 15, "scale exponent: the pair and its gaps are scaled by 10^severity"},
       {-6, -4, -2, 0, 2, 4, 6},
       &detail::scaledCase},
      {Category::kTinyFeatures,
       "tiny_features",
       {1, 15,
        "feature exponent: the only contact is a spike 10^-severity of the size of the plate "
        "it stands on"},
       {2, 4, 6},
       &detail::tinyFeaturesCase},
      {Category::kAxisRotations,
       "axis_rotations",
       {0, 16,
        "angle exponent: 0 rotations of exactly 90°/180° (exact matrices); s >= 1 turned a "
        "further 10^-s radians"},
       {0, 4, 8, 12, 16},
       &detail::axisRotationsCase},
      {Category::kMeshDefects,
       "mesh_defects",
       {1, 15,
        "gap exponent: planes and copies placed at exact contact and 10^-severity of the mesh's "
        "size to either side of it"},
       {3, 8, 13},
       &detail::meshDefectsCase},
      {Category::kDistance,
       "distance",
       {0, 8,
        "translation exponent: touching cubes and cubes one ulp to 1e-9 apart, crossing and "
        "2^-30 to 2^-50 apart sliver triangles, zero-area triangles on, one ulp off and one ulp "
        "inside a cube's face, edge and corner, all translated about 10^severity; asked for "
        "their distance"},
       {0, 3, 6, 8},
       &detail::distanceCase},
  }};
  return categories;
}

const CategoryInfo& info(Category category) {
  return table()[static_cast<std::size_t>(category)];
}

// SplitMix64's finaliser (Steele, Lea, Flood 2014): spreads each input bit over the seed.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// Case i's seed depends on nothing else, so a scene asking for more cases keeps the first ones.
std::uint64_t caseSeed(std::uint64_t seed, Category category, int severity, std::size_t index) {
  std::uint64_t h = mix(seed);
  h = mix(h ^ static_cast<std::uint64_t>(category));
  h = mix(h ^ static_cast<std::uint64_t>(static_cast<std::int64_t>(severity)));
  return mix(h ^ static_cast<std::uint64_t>(index));
}

}  // namespace

const std::vector<Category>& allCategories() {
  static const std::vector<Category> all = [] {
    std::vector<Category> out;
    for (const CategoryInfo& c : table())
      out.push_back(c.category);
    return out;
  }();
  return all;
}

const char* categoryName(Category category) {
  return info(category).name;
}

std::optional<Category> parseCategory(const std::string& name) {
  for (const CategoryInfo& c : table()) {
    if (name == c.name) return c.category;
  }
  return std::nullopt;
}

SeverityRange severityRange(Category category) {
  return info(category).severities;
}

std::vector<int> defaultSeverities(Category category) {
  return info(category).defaults;
}

Result<std::vector<StressCase>> generateStressCases(Category category, int severity,
                                                    std::size_t count, std::uint64_t seed,
                                                    const StressInputs& inputs) {
  const CategoryInfo& c = info(category);
  if (severity < c.severities.min || severity > c.severities.max) {
    return Status(StatusCode::kInvalidArgument,
                  std::string(c.name) + ": severity " + std::to_string(severity) + " is outside [" +
                      std::to_string(c.severities.min) + ", " + std::to_string(c.severities.max) +
                      "] (" + c.severities.meaning + ")");
  }
  if (category == Category::kMeshDefects) {
    if (inputs.defect_meshes.empty()) {
      return Status(StatusCode::kInvalidArgument,
                    "mesh_defects: needs at least one mesh with defects to pose");
    }
    for (const NamedMesh& m : inputs.defect_meshes) {
      if (!m.mesh || m.mesh->triangleCount() == 0) {
        return Status(StatusCode::kInvalidArgument,
                      "mesh_defects: mesh '" + m.name + "' has no triangles");
      }
    }
  }
  std::vector<StressCase> cases;
  cases.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    detail::Rng rng(caseSeed(seed, category, severity, i));
    const detail::CaseRequest request{severity, i, &inputs};
    StressCase one = c.generate(request, rng);
    one.category = category;
    one.severity = severity;
    one.index = i;
    one.name = std::string(c.name) + "/s" + std::to_string(severity) + "/" + std::to_string(i) +
               "/" + one.kind;
    cases.push_back(std::move(one));
  }
  return cases;
}

namespace detail {

StressCase caseOf(std::string kind, Placed placed, Aim aim) {
  StressCase out;
  out.kind = std::move(kind);
  out.a = std::make_shared<const TriangleMesh>(std::move(placed.a));
  out.b = std::make_shared<const TriangleMesh>(std::move(placed.b));
  out.pose_a = placed.pose_a;
  out.pose_b = placed.pose_b;
  out.aim = aim;
  return out;
}

}  // namespace detail
}  // namespace collido::stress
