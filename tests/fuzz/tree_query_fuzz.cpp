// tree_query_fuzz: the OBB tree's answers on fuzzed small meshes, against the exact oracle.
//
// Why: the OBB tree must be exact (issue 5): no missed and no extra triangle pair, touching
// counts as intersecting, whatever the rounding. The hard inputs are few and small (exactly
// touching or coplanar triangles, slivers, repeated and collinear corners, rotations by exact
// multiples of 90 degrees where separating-axis cross products vanish, coordinates far from the
// origin), so a fuzzer mutating a handful of vertices finds them faster than any sweep.
// What it checks, per input and for every tree variant (double and float boxes, the leaf size
// the input picks): collide's all-pairs answer is exactly collido::exactIntersectingPairs' set
// (no duplicates), its first-hit answer is a hit exactly when the oracle finds one, with a
// witness that truly intersects, and both trees are valid (ObbTree::validate: every triangle
// inside every ancestor's box). Any disagreement prints the input in full and both answers,
// then aborts (libFuzzer saves the reproducer).
//
// Input decoding (Bytes below; past the end every byte reads 0):
//   byte     leaf size (1 + b % 4)
//   mesh A   vertex count 3 + b % 6, triangle count 1 + b % 6; per vertex one byte picks
//            "repeat an earlier vertex", "collinear with two earlier ones" (a + t (b - a),
//            t in {1/2, 2, -1, 1/3}) or three coordinates; per triangle three indices b % n
//   mesh B   the same
//   pose A   rotation: one of the 24 rotations of the cube (exact, incl. 90 and 180 degrees), a
//            rotation by a multiple of 90 degrees plus a tiny angle, or a normalised quaternion;
//            then the translation's three coordinates
//   pose B   the same
// A coordinate byte gives a small integer (exact touching contacts), a dyadic fraction, one of
// the nasty values (0, +-1, tiny, subnormal, 1 +- eps, 1e8 and its neighbours, ...) or the next
// 8 bytes as a raw double. Inputs the scene loader would refuse are skipped: a NaN or infinite
// coordinate, one beyond 1e18 in magnitude (past the range issue 5 asks the tree to be exact on:
// far from the origin means up to 1e8) and poses that are not rigid within the loader's 1e-9.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <collido/mesh/triangle_mesh.h>
#include <collido/obbtree/collide.h>
#include <collido/obbtree/tree.h>
#include <collido/oracle/exact_oracle.h>

namespace {

using collido::Pose;
using collido::TriangleMesh;

constexpr double kMaxMagnitude = 1e18;
constexpr double kRotationTolerance = 1e-9;  // the scene loader's

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kNasty[] = {0.0,
                             1.0,
                             -1.0,
                             0.5,
                             -0.5,
                             2.0,
                             3.0,
                             1.0 / 3.0,
                             0.1,
                             1.0 + kEps,
                             1.0 - kEps / 2,
                             -1.0 - kEps,
                             kEps,
                             -kEps,
                             1e-15,
                             1e-300,
                             std::numeric_limits<double>::min(),
                             std::numeric_limits<double>::denorm_min(),
                             -std::numeric_limits<double>::denorm_min(),
                             1e-8,
                             1e8,
                             -1e8,
                             1e8 + 1.0,
                             1e8 - 0.5,
                             1e8 * (1.0 + kEps),
                             12345.678,
                             -0.0};
constexpr std::size_t kNastyCount = sizeof(kNasty) / sizeof(kNasty[0]);

// Reads the input front to back; past the end every byte is 0.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t next() { return pos_ < size_ ? data_[pos_++] : 0; }

  double raw() {
    std::uint8_t bytes[8];
    for (std::uint8_t& b : bytes)
      b = next();
    double value;
    std::memcpy(&value, bytes, sizeof value);
    return value;
  }

  /// A coordinate: bytes 0-63 a small integer in [-4, 4], 64-159 a nasty value, 160-223 a
  /// dyadic fraction in [-4, 3.875], 224-255 a raw double.
  double coordinate() {
    const std::uint8_t b = next();
    if (b < 64) return static_cast<double>(b % 9) - 4.0;
    if (b < 160) return kNasty[(b - 64) % kNastyCount];
    if (b < 224) return (static_cast<double>(b - 160) - 32.0) / 8.0;
    return raw();
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

bool usable(double v) {
  return std::isfinite(v) && std::abs(v) <= kMaxMagnitude;
}

/// Decodes a small mesh; false when a coordinate is unusable.
bool decodeMesh(Bytes& in, TriangleMesh& mesh) {
  const int vertex_count = 3 + in.next() % 6;
  const int triangle_count = 1 + in.next() % 6;
  mesh.vertices.resize(3, vertex_count);
  for (int v = 0; v < vertex_count; ++v) {
    const std::uint8_t op = in.next();
    if (op % 8 == 0 && v >= 1) {  // a repeated vertex
      mesh.vertices.col(v) = mesh.vertices.col(in.next() % v);
    } else if (op % 8 == 1 && v >= 2) {  // collinear with two earlier vertices
      constexpr double kT[] = {0.5, 2.0, -1.0, 1.0 / 3.0};
      const Eigen::Vector3d a = mesh.vertices.col(in.next() % v);
      const Eigen::Vector3d b = mesh.vertices.col(in.next() % v);
      mesh.vertices.col(v) = a + kT[in.next() % 4] * (b - a);
    } else {
      for (int k = 0; k < 3; ++k)
        mesh.vertices(k, v) = in.coordinate();
    }
  }
  mesh.triangles.resize(3, triangle_count);
  for (int t = 0; t < triangle_count; ++t) {
    for (int k = 0; k < 3; ++k)
      mesh.triangles(k, t) = in.next() % vertex_count;
  }
  return std::all_of(mesh.vertices.data(), mesh.vertices.data() + mesh.vertices.size(), usable);
}

/// The 24 rotations of the cube: signed permutation matrices with determinant +1.
std::vector<Eigen::Matrix3d> cubeRotations() {
  std::vector<Eigen::Matrix3d> out;
  std::array<int, 3> perm = {0, 1, 2};
  do {
    for (int signs = 0; signs < 8; ++signs) {
      Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
      for (int row = 0; row < 3; ++row)
        m(row, perm[static_cast<std::size_t>(row)]) = (signs >> row) & 1 ? -1.0 : 1.0;
      if (m.determinant() > 0.0) out.push_back(m);
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return out;
}

/// Decodes a pose; false when it is unusable (not rigid within the loader's tolerance, or a
/// translation coordinate out of range).
bool decodePose(Bytes& in, Pose& pose) {
  static const std::vector<Eigen::Matrix3d> kCube = cubeRotations();
  pose = Pose::Identity();
  const std::uint8_t kind = in.next() % 4;
  if (kind <= 1) {
    pose.linear() = kCube[in.next() % kCube.size()];
  } else if (kind == 2) {  // a multiple of 90 degrees plus a tiny angle, about a simple axis
    const Eigen::Vector3d kAxes[] = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                     Eigen::Vector3d::UnitZ(), Eigen::Vector3d(1, 1, 0),
                                     Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, -2, 3)};
    constexpr double kTiny[] = {0.0, 1e-15, -1e-15, 1e-12, 1e-9, -1e-6, 1e-3, 2 * kEps};
    const Eigen::Vector3d axis = kAxes[in.next() % 6].normalized();
    const double angle = (in.next() % 4) * (M_PI / 2) + kTiny[in.next() % 8];
    pose.linear() = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
  } else {  // a normalised quaternion
    Eigen::Quaterniond q;
    q.w() = in.coordinate();
    q.x() = in.coordinate();
    q.y() = in.coordinate();
    q.z() = in.coordinate();
    const double norm = q.norm();
    if (!(std::isfinite(norm) && norm > 1e-6)) return false;
    pose.linear() = q.normalized().toRotationMatrix();
  }
  for (int k = 0; k < 3; ++k)
    pose.translation()(k) = in.coordinate();
  if (!pose.translation().allFinite() || !usable(pose.translation().cwiseAbs().maxCoeff()))
    return false;
  const Eigen::Matrix3d r = pose.linear();
  const double drift = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  return r.allFinite() && drift <= kRotationTolerance && r.determinant() > 0.0;
}

void printMesh(const char* name, const TriangleMesh& mesh) {
  std::fprintf(stderr, "mesh %s: %ld vertices, %ld triangles\n", name,
               static_cast<long>(mesh.vertices.cols()), static_cast<long>(mesh.triangles.cols()));
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v) {
    std::fprintf(stderr, "  v%ld = (%.17g, %.17g, %.17g)\n", static_cast<long>(v),
                 mesh.vertices(0, v), mesh.vertices(1, v), mesh.vertices(2, v));
  }
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    std::fprintf(stderr, "  t%ld = (%d, %d, %d)\n", static_cast<long>(t), mesh.triangles(0, t),
                 mesh.triangles(1, t), mesh.triangles(2, t));
  }
}

void printPose(const char* name, const Pose& pose) {
  std::fprintf(stderr, "pose %s (rotation rows | translation):\n", name);
  for (int row = 0; row < 3; ++row) {
    std::fprintf(stderr, "  %.17g %.17g %.17g | %.17g\n", pose.linear()(row, 0),
                 pose.linear()(row, 1), pose.linear()(row, 2), pose.translation()(row));
  }
}

std::string pairsText(const std::vector<collido::TrianglePair>& pairs) {
  std::string out = "{";
  for (const collido::TrianglePair& p : pairs) {
    out += (out.size() > 1 ? " (" : "(") + std::to_string(p.a) + "," + std::to_string(p.b) + ")";
  }
  return out + "}";
}

struct Case {
  TriangleMesh a;
  TriangleMesh b;
  Pose pose_a;
  Pose pose_b;
};

[[noreturn]] void disagree(const Case& c, const collido::obbtree::BuildOptions& options,
                           const std::string& what, const std::string& tree_answer,
                           const std::string& oracle_answer) {
  std::fprintf(stderr, "\ntree_query_fuzz: the OBB tree disagrees with the exact oracle: %s\n",
               what.c_str());
  std::fprintf(stderr, "tree options: max_leaf_triangles=%d float_boxes=%s\n",
               static_cast<int>(options.max_leaf_triangles),
               options.float_boxes ? "true" : "false");
  printMesh("A", c.a);
  printMesh("B", c.b);
  printPose("A", c.pose_a);
  printPose("B", c.pose_b);
  std::fprintf(stderr, "tree:   %s\noracle: %s\n", tree_answer.c_str(), oracle_answer.c_str());
  std::abort();
}

std::vector<collido::TrianglePair> toPairs(const collido::obbtree::CollideResult& result) {
  std::vector<collido::TrianglePair> out;
  for (const collido::obbtree::TrianglePair& p : result.pairs)
    out.push_back({p.a, p.b});
  return out;
}

void checkVariant(const Case& c, const collido::obbtree::BuildOptions& options,
                  const collido::OracleAnswer& oracle) {
  using collido::obbtree::CollideMode;
  const auto tree_a = collido::obbtree::ObbTree::build(c.a.vertices, c.a.triangles, options);
  const auto tree_b = collido::obbtree::ObbTree::build(c.b.vertices, c.b.triangles, options);
  const std::string oracle_text = pairsText(oracle.pairs);

  collido::obbtree::CollideResult result;
  collido::obbtree::collide(tree_a, c.pose_a, tree_b, c.pose_b, {CollideMode::kAllPairs, 0},
                            result);
  std::vector<collido::TrianglePair> pairs = toPairs(result);
  std::sort(pairs.begin(), pairs.end());
  if (pairs != oracle.pairs || result.truncated)
    disagree(c, options, "all pairs", pairsText(pairs), oracle_text);

  collido::obbtree::collide(tree_a, c.pose_a, tree_b, c.pose_b, {CollideMode::kFirstHit, 0},
                            result);
  pairs = toPairs(result);
  const bool hit = !pairs.empty();
  if (hit != oracle.intersecting || pairs.size() > 1) {
    disagree(c, options, "first hit", hit ? "hit " + pairsText(pairs) : "no hit",
             oracle.intersecting ? "hit " + oracle_text : "no hit");
  }
  if (hit && !std::binary_search(oracle.pairs.begin(), oracle.pairs.end(), pairs[0])) {
    disagree(c, options, "first hit's witness does not intersect", pairsText(pairs), oracle_text);
  }
  // Last, so that a wrong answer is reported as such: the invariant the answers rest on.
  for (const char* side : {"A", "B"}) {
    const std::string problem = (side[0] == 'A' ? tree_a : tree_b).validate();
    if (!problem.empty()) {
      disagree(c, options, std::string("tree ") + side + " is invalid: " + problem, "answers agree",
               oracle_text);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  const auto leaf_size = static_cast<std::int32_t>(1 + in.next() % 4);
  Case c;
  if (!decodeMesh(in, c.a) || !decodeMesh(in, c.b)) return -1;
  if (!decodePose(in, c.pose_a) || !decodePose(in, c.pose_b)) return -1;

  const collido::OracleAnswer oracle =
      collido::exactIntersectingPairs(c.a, c.pose_a, c.b, c.pose_b, collido::OracleMode::kAllPairs);
  for (const bool float_boxes : {false, true}) {
    collido::obbtree::BuildOptions options;
    options.max_leaf_triangles = leaf_size;
    options.float_boxes = float_boxes;
    checkVariant(c, options, oracle);
  }
  return 0;
}
