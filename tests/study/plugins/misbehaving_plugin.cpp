// A test plugin whose variants misbehave the ways real engines do, so that a study can mix them
// with well-behaved backends and show that each costs one combination only:
//   misbehaving:exact  answers correctly (brute force over every triangle pair, floating-point
//                      separating-axis test); option build_mib=N keeps N MiB of heap per model
//   misbehaving:crash  dies of SIGSEGV in query()
//   misbehaving:abort  calls std::abort() in query()
//   misbehaving:hang   never returns from query()
//   misbehaving:exit   ends the process with exit code 7 in query()
//   misbehaving:throw  throws in query() (the adapter turns it into a failed query)
//   misbehaving:wrong  always answers "disjoint"
//   misbehaving:crash_in_build, misbehaving:abort_in_build, misbehaving:hang_in_build
//                      the same failures in build(), before any query
//   misbehaving:crash_in_create  dies of SIGSEGV when an instance is created
// Every answering variant also spends COLLIDO_TEST_QUERY_EXTRA_US microseconds (an environment
// variable, so that the setting keeps its name) busy in each query, which steadies its time between
// studies of the same settings. COLLIDO_TEST_QUERY_SLOWDOWN=F makes each whole query (that
// spin and the answer) 1 + F times as long, a known slowdown `collido compare` must find. With
// COLLIDO_TEST_QUERY_JITTER=J and COLLIDO_TEST_QUERY_JITTER_FILE=F, every other instance created
// (counted by appending a byte to F) makes each whole query 1 + J times as long as well: worker
// processes, and so a study's rounds, that disagree by a known factor.
// Built as libcollido_plugin_misbehaving.so into the tests' own plugin folder, so only tests
// that pass that folder with --plugin see it.
#include <array>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <collido/plugin_export.h>

namespace misbehaving {
namespace {

using collido::QueryKind;
using Vec = Eigen::Vector3d;
using Triangle = std::array<Vec, 3>;

enum class Mode {
  kExact,
  kCrash,
  kAbort,
  kHang,
  kExit,
  kThrow,
  kWrong,
  kCrashInBuild,
  kAbortInBuild,
  kHangInBuild
};

class MeshModel final : public collido::BackendModel {
 public:
  MeshModel(const collido::MeshView& mesh, std::size_t ballast_bytes)
      : vertices(mesh.vertices), triangles(mesh.triangles), ballast(ballast_bytes, 1) {}
  // Leaves the ballast out on purpose: the heap probe must find it whatever the backend says.
  std::size_t memoryBytes() const override {
    return sizeof(*this) + static_cast<std::size_t>(vertices.size()) * sizeof(double) +
           static_cast<std::size_t>(triangles.size()) * sizeof(int);
  }
  Eigen::Matrix3Xd vertices;
  Eigen::Matrix3Xi triangles;
  std::vector<unsigned char> ballast;
};

std::vector<Triangle> posed(const MeshModel& m, const collido::Pose& pose) {
  std::vector<Triangle> out(static_cast<std::size_t>(m.triangles.cols()));
  for (Eigen::Index t = 0; t < m.triangles.cols(); ++t) {
    for (int k = 0; k < 3; ++k)
      out[static_cast<std::size_t>(t)][k] = pose * m.vertices.col(m.triangles(k, t));
  }
  return out;
}

bool separatedAlong(const Vec& axis, const Triangle& a, const Triangle& b) {
  if (axis.squaredNorm() == 0.0) return false;
  double a_lo = axis.dot(a[0]), a_hi = a_lo, b_lo = axis.dot(b[0]), b_hi = b_lo;
  for (int k = 1; k < 3; ++k) {
    a_lo = std::min(a_lo, axis.dot(a[k]));
    a_hi = std::max(a_hi, axis.dot(a[k]));
    b_lo = std::min(b_lo, axis.dot(b[k]));
    b_hi = std::max(b_hi, axis.dot(b[k]));
  }
  return a_hi < b_lo || b_hi < a_lo;
}

// The example plugin's test (examples/brute_force_plugin): face normals, edge cross products,
// and in-plane edge normals for coplanar pairs.
bool trianglesOverlap(const Triangle& a, const Triangle& b) {
  const Vec na = (a[1] - a[0]).cross(a[2] - a[0]);
  const Vec nb = (b[1] - b[0]).cross(b[2] - b[0]);
  if (separatedAlong(na, a, b) || separatedAlong(nb, a, b)) return false;
  for (int i = 0; i < 3; ++i) {
    const Vec ea = a[(i + 1) % 3] - a[i];
    const Vec eb = b[(i + 1) % 3] - b[i];
    for (int j = 0; j < 3; ++j) {
      if (separatedAlong(ea.cross(b[(j + 1) % 3] - b[j]), a, b)) return false;
    }
    if (separatedAlong(na.cross(ea), a, b) || separatedAlong(nb.cross(eb), a, b)) return false;
  }
  return true;
}

[[noreturn]] void crash() {
  // Restore the default action first, so the process dies of the signal even where a sanitizer
  // has installed its own SIGSEGV handler (which would turn it into an exit code).
  std::signal(SIGSEGV, SIG_DFL);
  std::raise(SIGSEGV);
  std::abort();  // not reached
}

[[noreturn]] void hang() {
  for (;;)
    std::this_thread::sleep_for(std::chrono::seconds(1));
}

// A number from the environment, 0 without it.
double environmentNumber(const char* name) {
  const char* text = std::getenv(name);
  return text == nullptr ? 0.0 : std::strtod(text, nullptr);
}

// Whether this instance is one of the jittered ones: every other instance created, counted in
// the file COLLIDO_TEST_QUERY_JITTER_FILE names; none without it or without a jitter.
bool jitteredInstance() {
  const char* counter = std::getenv("COLLIDO_TEST_QUERY_JITTER_FILE");
  if (environmentNumber("COLLIDO_TEST_QUERY_JITTER") == 0.0 || counter == nullptr) return false;
  const int file = open(counter, O_WRONLY | O_APPEND | O_CREAT, 0644);
  if (file < 0) return false;
  struct stat status {};
  const bool counted = write(file, "+", 1) == 1 && fstat(file, &status) == 0;
  close(file);
  return counted && status.st_size % 2 == 0;
}

// How much longer than itself each whole query is made: the slowdown, plus the jitter on the
// jittered instances.
double querySlowdown() {
  const double slowdown = environmentNumber("COLLIDO_TEST_QUERY_SLOWDOWN");
  return jitteredInstance() ? slowdown + environmentNumber("COLLIDO_TEST_QUERY_JITTER") : slowdown;
}

// Spins (a sleep would give the core away and wake late) until `microseconds` have passed.
void spin(double microseconds) {
  const auto until =
      std::chrono::steady_clock::now() + std::chrono::duration<double, std::micro>(microseconds);
  while (std::chrono::steady_clock::now() < until) {
  }
}

class MisbehavingBackend final : public collido::Backend {
 public:
  MisbehavingBackend(Mode mode, std::size_t ballast_bytes)
      : mode_(mode),
        ballast_bytes_(ballast_bytes),
        extra_us_(environmentNumber("COLLIDO_TEST_QUERY_EXTRA_US")),
        slowdown_(querySlowdown()) {}

  collido::Capabilities capabilities() const override {
    collido::Capabilities caps;
    caps.shape_kinds = static_cast<std::uint32_t>(collido::ShapeKind::kTriangleMesh);
    caps.queries = collido::QueryKindSet(QueryKind::kBoolean) | QueryKind::kAllPairs;
    caps.update = true;
    caps.counts_primitive_tests = true;
    caps.notes = "test plugin: misbehaves on purpose";
    return caps;
  }

  collido::Result<std::unique_ptr<collido::BackendModel>> build(
      const collido::MeshView& mesh, const collido::BuildNeeds& /*needs*/,
      const collido::StateSibling& /*sibling*/) override {
    if (mode_ == Mode::kCrashInBuild) crash();
    if (mode_ == Mode::kAbortInBuild) std::abort();
    if (mode_ == Mode::kHangInBuild) hang();
    return std::unique_ptr<collido::BackendModel>(
        std::make_unique<MeshModel>(mesh, ballast_bytes_));
  }

  collido::Status update(collido::BackendModel& model,
                         const Eigen::Ref<const Eigen::Matrix3Xd>& positions,
                         collido::UpdateCounters& /*counters*/) override {
    static_cast<MeshModel&>(model).vertices = positions;
    return {};
  }

  collido::Status query(collido::BackendModel& a, const collido::Pose& pose_a,
                        collido::BackendModel& b, const collido::Pose& pose_b,
                        const collido::QueryRequest& request,
                        collido::QueryResult& result) override {
    switch (mode_) {
      case Mode::kCrash:
        crash();
      case Mode::kAbort:
        std::abort();
      case Mode::kHang:
        hang();
      case Mode::kExit:
        std::_Exit(7);
      case Mode::kThrow:
        throw std::runtime_error("misbehaving:throw throws on purpose");
      case Mode::kWrong:
        if (extra_us_ > 0.0) spin(extra_us_);
        return {};
      case Mode::kExact:
      case Mode::kCrashInBuild:
      case Mode::kAbortInBuild:
      case Mode::kHangInBuild:
        break;
    }
    const auto start = std::chrono::steady_clock::now();
    if (extra_us_ > 0.0) spin(extra_us_);
    const collido::Status answered = answer(a, pose_a, b, pose_b, request, result);
    // The slowdown scales the whole query, whatever the build's own cost (sanitizers included).
    if (slowdown_ > 0.0) {
      spin(slowdown_ *
           std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
               .count());
    }
    return answered;
  }

 private:
  // The brute-force answer: every triangle pair by the separating-axis test.
  static collido::Status answer(collido::BackendModel& a, const collido::Pose& pose_a,
                                collido::BackendModel& b, const collido::Pose& pose_b,
                                const collido::QueryRequest& request,
                                collido::QueryResult& result) {
    const std::vector<Triangle> ta = posed(static_cast<MeshModel&>(a), pose_a);
    const std::vector<Triangle> tb = posed(static_cast<MeshModel&>(b), pose_b);
    result.counters.counts_primitive_tests = true;
    for (std::size_t i = 0; i < ta.size(); ++i) {
      for (std::size_t j = 0; j < tb.size(); ++j) {
        ++result.counters.primitive_tests;
        if (!trianglesOverlap(ta[i], tb[j])) continue;
        result.intersecting = true;
        if (request.kind == QueryKind::kAllPairs && request.max_pairs != 0 &&
            result.pairs.size() >= request.max_pairs) {
          result.truncated = true;
          return {};
        }
        result.pairs.push_back(
            collido::TrianglePair{static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)});
        if (request.kind == QueryKind::kBoolean) return {};
      }
    }
    return {};
  }

  Mode mode_;
  std::size_t ballast_bytes_;
  double extra_us_;
  double slowdown_;
};

collido::Result<std::unique_ptr<collido::Backend>> create(const std::string& variant,
                                                          collido::BackendOptions& options) {
  Mode mode = Mode::kExact;
  if (variant == "misbehaving:crash") mode = Mode::kCrash;
  if (variant == "misbehaving:abort") mode = Mode::kAbort;
  if (variant == "misbehaving:hang") mode = Mode::kHang;
  if (variant == "misbehaving:exit") mode = Mode::kExit;
  if (variant == "misbehaving:throw") mode = Mode::kThrow;
  if (variant == "misbehaving:wrong") mode = Mode::kWrong;
  if (variant == "misbehaving:crash_in_build") mode = Mode::kCrashInBuild;
  if (variant == "misbehaving:abort_in_build") mode = Mode::kAbortInBuild;
  if (variant == "misbehaving:hang_in_build") mode = Mode::kHangInBuild;
  if (variant == "misbehaving:crash_in_create") crash();
  const collido::Result<std::int64_t> mib = options.getInt("build_mib", 0, 0, 1024);
  if (!mib.ok()) return mib.status();
  return std::unique_ptr<collido::Backend>(std::make_unique<MisbehavingBackend>(
      mode, static_cast<std::size_t>(mib.value()) * 1024 * 1024));
}

const collido::PluginInfo& describe() {
  static const collido::PluginInfo info{
      "misbehaving",
      "1.0.0",
      "none (test plugin)",
      "1.0.0",
      {{"misbehaving:exact", "brute force, right answers; build_mib=N keeps N MiB per model"},
       {"misbehaving:crash", "SIGSEGV in query"},
       {"misbehaving:abort", "std::abort in query"},
       {"misbehaving:hang", "never returns from query"},
       {"misbehaving:exit", "exits with code 7 in query"},
       {"misbehaving:throw", "throws in query"},
       {"misbehaving:wrong", "always answers disjoint"},
       {"misbehaving:crash_in_build", "SIGSEGV in build"},
       {"misbehaving:abort_in_build", "std::abort in build"},
       {"misbehaving:hang_in_build", "never returns from build"},
       {"misbehaving:crash_in_create", "SIGSEGV when created"}},
      &create};
  return info;
}

}  // namespace
}  // namespace misbehaving

COLLIDO_EXPORT_PLUGIN(misbehaving, misbehaving::describe)
