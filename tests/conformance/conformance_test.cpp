// The plugin conformance kit: one parameterised suite, written once, run against every plugin.
//
// Hard requirements (any plugin): the table and capabilities are sane, another interface version
// is refused, unsupported requests answer "unsupported", bad handles are errors, state siblings
// answer for their own shapes and survive each other, results obey the contact conventions, a crash
// fails the run (each plugin runs in its own process). Measurements held to a committed record:
// every answer against the exact oracle on the bundled scenes and the kit's own adversarial scenes.
// A variant must be exact unless its expectations file
// (tests/conformance/expectations/<variant>.json) records, per scene and query, the counts of its
// disagreements; then those counts must be met exactly, so a change in an engine's behaviour, for
// better or worse, is noticed and reviewed instead of hidden by a tolerance.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include <collido/host/backend_instance.h>
#include <collido/mesh/procedural.h>
#include <collido/nurbs/surface_generators.h>
#include <collido/oracle/distance_oracle.h>
#include <collido/oracle/exact_oracle.h>
#include <collido/runner/runner.h>

#include "conformance_target.h"
#include "expectations.h"
#include "scene_cases.h"

namespace collido::conformance {
namespace {

// Skips with a reason that also reaches the JSON report (GoogleTest keeps skip messages out of
// it), where `collido conformance` reads it.
#define COLLIDO_KIT_SKIP(reason)                            \
  do {                                                      \
    const std::string kit_reason_ = (reason);               \
    ::testing::Test::RecordProperty("detail", kit_reason_); \
    GTEST_SKIP() << kit_reason_;                            \
  } while (false)

std::unique_ptr<BackendInstance> createInstance(const Target& target) {
  Result<std::unique_ptr<BackendInstance>> instance =
      BackendInstance::create(target.library, target.variant, target.options);
  EXPECT_TRUE(instance.ok()) << instance.status().message();
  return instance.ok() ? std::move(instance).value() : nullptr;
}

TriangleMesh sphere(double radius, int slices, int stacks) {
  Result<TriangleMesh> mesh = makeSphere(SphereParams{radius, slices, stacks});
  EXPECT_TRUE(mesh.ok());
  return std::move(mesh).value();
}

Pose moved(double x) {
  Pose pose = Pose::Identity();
  pose.translation() = Eigen::Vector3d(x, 0.0, 0.0);
  return pose;
}

// A small shape of the kind the backend builds: a sphere mesh, or (surface-only backends) a zone
// of a sphere as an exact NURBS surface. Both lie within the unit ball about the origin.
struct SampleShape {
  TriangleMesh mesh;
  nurbs::NurbsSurface surface;
};

const SampleShape& sampleShape() {
  static const SampleShape shape{sphere(1.0, 8, 4),
                                 nurbs::sphereZone(Eigen::Vector3d::Zero(), 1.0, 0.0)};
  return shape;
}

Result<ModelHandle> buildSample(BackendInstance& backend, const BuildNeeds& needs) {
  if (backend.capabilities().buildsShape(ShapeKind::kTriangleMesh)) {
    return backend.build(sampleShape().mesh.view(), needs);
  }
  return backend.build(nurbs::viewOf(sampleShape().surface), needs);
}

// --- the interface ---------------------------------------------------------------------------

class Interface : public ::testing::TestWithParam<std::size_t> {
 protected:
  const Target& target() const { return targets()[GetParam()]; }

  // Holds a measurement to the variant's recorded expectations (recording it when the kit is
  // asked to): a changed count fails, naming the file; `context` is added to the report.
  void expectAsRecorded(const std::string& key, const Disagreement& measured,
                        const std::string& context = "") {
    Result<Expectations> expectations =
        loadExpectations(settings().expectations_dir, target().variant);
    ASSERT_TRUE(expectations.ok()) << expectations.status().message();
    if (!settings().write_expectations_dir.empty()) {
      ASSERT_TRUE(
          recordMeasurement(settings().write_expectations_dir, target().variant, key, measured)
              .ok());
    }
    const Disagreement expected = expectations.value().expectedFor(key);
    if (!expected.none()) RecordProperty("detail", "as recorded: " + expected.toString() + context);
    if (!(measured == expected))
      ADD_FAILURE() << key << ": measured " << measured.toString() << "; expected "
                    << expected.toString() << " ("
                    << (expectations.value().file.empty() ? "no expectations file: must be exact"
                                                          : expectations.value().file)
                    << ")" << context;
  }
};

TEST_P(Interface, TableAndCapabilitiesAreSane) {
  const CollidoPluginTable& table = target().library->table();
  EXPECT_EQ(table.abi_version, COLLIDO_PLUGIN_ABI_VERSION);
  EXPECT_GE(table.struct_size, sizeof(CollidoPluginTable));
  EXPECT_NE(std::strlen(table.plugin_version), 0u);
  EXPECT_NE(std::strlen(table.engine_version), 0u);
  std::unique_ptr<BackendInstance> backend = createInstance(target());
  ASSERT_TRUE(backend);
  const Capabilities& caps = backend->capabilities();
  EXPECT_TRUE(caps.buildsShape(ShapeKind::kTriangleMesh) ||
              caps.buildsShape(ShapeKind::kNurbsSurface))
      << "builds no shape kind";
  EXPECT_FALSE(caps.queries.empty()) << "answers no query kind";
}

TEST_P(Interface, RefusesAnotherInterfaceVersion) {
  CollidoPluginTable altered = target().library->table();
  altered.abi_version = COLLIDO_PLUGIN_ABI_VERSION + 1;
  const Status refused = checkPluginTable(&altered, target().library->path());
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.message().find(std::to_string(COLLIDO_PLUGIN_ABI_VERSION + 1)),
            std::string::npos)
      << refused.message();
  EXPECT_NE(refused.message().find(std::to_string(COLLIDO_PLUGIN_ABI_VERSION)), std::string::npos);
}

TEST_P(Interface, RejectsUnknownOptions) {
  Result<std::unique_ptr<BackendInstance>> instance = BackendInstance::create(
      target().library, target().variant, {{"no_such_option_anywhere", "1"}});
  ASSERT_FALSE(instance.ok());
  EXPECT_EQ(instance.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(instance.status().message().find("no_such_option_anywhere"), std::string::npos)
      << instance.status().message();
}

TEST_P(Interface, UnsupportedRequestsAnswerUnsupported) {
  std::unique_ptr<BackendInstance> backend = createInstance(target());
  ASSERT_TRUE(backend);
  const QueryKindSet supported = backend->capabilities().queries;
  std::vector<QueryKind> missing;
  for (const QueryKindInfo& kind : kQueryKinds) {
    if (!supported.contains(kind.kind)) missing.push_back(kind.kind);
  }
  if (missing.empty()) COLLIDO_KIT_SKIP(target().variant + " answers every query kind");
  for (QueryKind kind : missing) {
    Result<ModelHandle> refused = buildSample(*backend, BuildNeeds{QueryKindSet(kind)});
    ASSERT_FALSE(refused.ok()) << queryKindName(kind);
    EXPECT_EQ(refused.status().code(), StatusCode::kUnsupported) << refused.status().message();
  }
  Result<ModelHandle> a = buildSample(*backend, BuildNeeds{supported});
  Result<ModelHandle> b = buildSample(*backend, BuildNeeds{supported});
  ASSERT_TRUE(a.ok() && b.ok());
  QueryResult result;
  for (QueryKind kind : missing) {
    QueryRequest request;
    request.kind = kind;
    const Status s =
        backend->query(a.value(), Pose::Identity(), b.value(), moved(0.5), request, result);
    EXPECT_EQ(s.code(), StatusCode::kUnsupported) << queryKindName(kind) << ": " << s.toString();
  }
}

TEST_P(Interface, BadHandlesAreErrors) {
  std::unique_ptr<BackendInstance> backend = createInstance(target());
  ASSERT_TRUE(backend);
  const QueryKindSet supported = backend->capabilities().queries;
  Result<ModelHandle> a = buildSample(*backend, BuildNeeds{supported});
  Result<ModelHandle> b = buildSample(*backend, BuildNeeds{supported});
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_TRUE(backend->release(b.value()).ok());
  QueryRequest request;
  request.kind =
      std::find_if(std::begin(kQueryKinds), std::end(kQueryKinds), [&](const QueryKindInfo& k) {
        return supported.contains(k.kind);
      })->kind;
  QueryResult result;
  for (ModelHandle bad : {b.value(), ModelHandle{0}, a.value() + 12345}) {
    const Status s = backend->query(a.value(), Pose::Identity(), bad, moved(0.5), request, result);
    EXPECT_EQ(s.code(), StatusCode::kInvalidHandle) << "handle " << bad << ": " << s.toString();
  }
  EXPECT_EQ(backend->release(b.value()).code(), StatusCode::kInvalidHandle);
  EXPECT_FALSE(backend->memory(b.value()).ok());
}

// Another active state of an object, built as the first state's sibling (state_of): it answers
// for its own shape, the first state for its own, and it survives the first state's release.
// A sibling with another triangle list, or a dead one, is refused.
TEST_P(Interface, StateSiblingsAnswerForTheirOwnShape) {
  std::unique_ptr<BackendInstance> backend = createInstance(target());
  ASSERT_TRUE(backend);
  if (!backend->capabilities().buildsShape(ShapeKind::kTriangleMesh)) {
    COLLIDO_KIT_SKIP(target().variant + " builds no triangle meshes");
  }
  const QueryKindSet supported = backend->capabilities().queries;
  if (!supported.contains(QueryKind::kBoolean)) COLLIDO_KIT_SKIP("answers no boolean queries");
  const BuildNeeds needs{QueryKindSet(QueryKind::kBoolean)};
  const TriangleMesh small = sphere(0.5, 24, 12);
  TriangleMesh large = small;  // the same triangle list, twice the size
  large.vertices *= 2.0;
  const TriangleMesh other = sphere(1.0, 24, 12);
  Result<ModelHandle> first = backend->build(small.view(), needs);
  ASSERT_TRUE(first.ok()) << first.status().toString();
  Result<ModelHandle> second = backend->build(large.view(), needs, first.value());
  ASSERT_TRUE(second.ok()) << second.status().toString();
  Result<ModelHandle> b = backend->build(other.view(), needs);
  ASSERT_TRUE(b.ok());
  // B (radius 1) 1.75 away: 0.25 from the small sphere, overlapping the large one by 0.25.
  QueryRequest request;
  request.kind = QueryKind::kBoolean;
  QueryResult result;
  ASSERT_TRUE(
      backend->query(first.value(), Pose::Identity(), b.value(), moved(1.75), request, result)
          .ok());
  EXPECT_FALSE(result.intersecting) << "the first state must answer for its own shape";
  ASSERT_TRUE(
      backend->query(second.value(), Pose::Identity(), b.value(), moved(1.75), request, result)
          .ok());
  EXPECT_TRUE(result.intersecting) << "the second state must answer for its own shape";
  ASSERT_TRUE(backend->release(first.value()).ok());
  ASSERT_TRUE(
      backend->query(second.value(), Pose::Identity(), b.value(), moved(1.75), request, result)
          .ok());
  EXPECT_TRUE(result.intersecting) << "a state must outlive its sibling";
  EXPECT_TRUE(backend->memory(second.value()).ok());

  // Refusals: a sibling that is gone, and one with another triangle list.
  Result<ModelHandle> orphan = backend->build(large.view(), needs, first.value());
  ASSERT_FALSE(orphan.ok());
  EXPECT_EQ(orphan.status().code(), StatusCode::kInvalidHandle) << orphan.status().toString();
  const TriangleMesh coarse = sphere(1.0, 12, 6);
  Result<ModelHandle> mismatched = backend->build(coarse.view(), needs, second.value());
  ASSERT_FALSE(mismatched.ok());
  EXPECT_EQ(mismatched.status().code(), StatusCode::kInvalidArgument)
      << mismatched.status().toString();
  EXPECT_NE(mismatched.status().message().find("triangle list"), std::string::npos)
      << mismatched.status().toString();
}

// --- contacts --------------------------------------------------------------------------------

// Two spheres overlapping along +x: every contact must be finite, its normal a unit vector
// pointing from A towards B (+x, give or take the facets), its depth >= 0, its triangles real.
TEST_P(Interface, ContactsFollowTheConventions) {
  std::unique_ptr<BackendInstance> backend = createInstance(target());
  ASSERT_TRUE(backend);
  if (!backend->capabilities().buildsShape(ShapeKind::kTriangleMesh)) {
    COLLIDO_KIT_SKIP(target().variant + " builds no triangle meshes");
  }
  if (!backend->capabilities().queries.contains(QueryKind::kContacts)) {
    COLLIDO_KIT_SKIP(target().variant + " does not answer contacts queries");
  }
  const TriangleMesh mesh = sphere(1.0, 32, 16);
  const BuildNeeds needs{QueryKindSet(QueryKind::kContacts)};
  Result<ModelHandle> a = backend->build(mesh.view(), needs);
  Result<ModelHandle> b = backend->build(mesh.view(), needs);
  ASSERT_TRUE(a.ok() && b.ok());
  QueryRequest request;
  request.kind = QueryKind::kContacts;
  QueryResult result;
  ASSERT_TRUE(
      backend->query(a.value(), Pose::Identity(), b.value(), moved(1.9), request, result).ok());
  ASSERT_TRUE(result.intersecting);
  ASSERT_FALSE(result.contacts.empty()) << "intersecting, but no contact reported";
  Eigen::Vector3d mean_normal = Eigen::Vector3d::Zero();
  const auto triangles = static_cast<std::int32_t>(mesh.triangleCount());
  for (const Contact& c : result.contacts) {
    ASSERT_TRUE(c.position.allFinite() && c.normal.allFinite() && std::isfinite(c.depth));
    EXPECT_NEAR(c.normal.norm(), 1.0, 1e-6);
    EXPECT_GE(c.depth, 0.0);
    EXPECT_TRUE(c.triangle_a == -1 || (c.triangle_a >= 0 && c.triangle_a < triangles));
    EXPECT_TRUE(c.triangle_b == -1 || (c.triangle_b >= 0 && c.triangle_b < triangles));
    // The overlap of the two unit spheres lies within x in [0.9, 1.0], |y|,|z| < 0.45.
    EXPECT_GT(c.position.x(), 0.85);
    EXPECT_LT(c.position.x(), 1.05);
    mean_normal += c.normal;
  }
  EXPECT_GT(mean_normal.normalized().x(), 0.9)
      << "contact normals must point from A towards B (+x); mean " << mean_normal.transpose();

  // Against the exact contacts (docs/DESIGN.md, "Contact geometry"), as the
  // "contacts/spheres" expectation: the sets the contacts stand for, their normals and depths.
  const OracleAnswer truth = exactIntersectingPairs(mesh, Pose::Identity(), mesh, moved(1.9));
  FrameRecord record;
  compareWithOracle(mesh, Pose::Identity(), mesh, moved(1.9), request, result, truth, record);
  ASSERT_TRUE(record.contact);
  expectAsRecorded("contacts/spheres", disagreementOf(record, QueryKind::kContacts),
                   " (" + contactScoreText(*record.contact) + ")");
}

// --- distance ----------------------------------------------------------------------------------

// Two spheres, one the mirror image of the other, at gaps from apart to touching exactly (a
// shared vertex) to overlapping: every answer against the exact distance, within rounding; then
// a loose tolerance must still hold. Counted as the "distance/spheres" expectation.
TEST_P(Interface, DistanceAnswersTheGapBetweenTwoSpheres) {
  std::unique_ptr<BackendInstance> backend = createInstance(target());
  ASSERT_TRUE(backend);
  if (!backend->capabilities().buildsShape(ShapeKind::kTriangleMesh)) {
    COLLIDO_KIT_SKIP(target().variant + " builds no triangle meshes");
  }
  if (!backend->capabilities().queries.contains(QueryKind::kDistance)) {
    COLLIDO_KIT_SKIP(target().variant + " answers no distance queries");
  }
  const TriangleMesh one = sphere(1.0, 16, 8);
  TriangleMesh mirrored = one;
  mirrored.vertices.row(0) *= -1.0;
  const BuildNeeds needs{QueryKindSet(QueryKind::kDistance)};
  Result<ModelHandle> a = backend->build(one.view(), needs);
  Result<ModelHandle> b = backend->build(mirrored.view(), needs);
  ASSERT_TRUE(a.ok() && b.ok());
  Disagreement sum;
  QueryResult result;
  for (const double rel_tolerance : {0.0, 0.1}) {
    for (const double gap : {0.75, 1e-4, 0.0, -0.3}) {
      const Pose pose_b = moved(2.0 + gap);
      QueryRequest request;
      request.kind = QueryKind::kDistance;
      request.rel_tolerance = rel_tolerance;
      ASSERT_TRUE(
          backend->query(a.value(), Pose::Identity(), b.value(), pose_b, request, result).ok());
      OracleAnswer truth;
      truth.distance = exactMeshDistance(one, Pose::Identity(), mirrored, pose_b);
      truth.intersecting = truth.distance->distance == 0.0;
      FrameRecord record;
      compareWithOracle(one, Pose::Identity(), mirrored, pose_b, request, result, truth, record);
      const Disagreement d = disagreementOf(record, QueryKind::kDistance);
      sum.disagreeing_frames += d.disagreeing_frames;
      sum.false_negatives += d.false_negatives;
      sum.false_positives += d.false_positives;
      sum.invalid_pairs += d.invalid_pairs;
    }
  }
  expectAsRecorded("distance/spheres", sum);
}

// Two zones of unit spheres facing each other along x (A about the origin, B about (2 + gap, 0,
// 0)), exact NURBS surfaces: the true distance is max(gap, 0) (at gap 0 they touch at one point,
// below it they cross). Asked with an absolute and with a relative tolerance; an answer counts as
// disagreeing when it fails, lies below the truth by more than rounding (1e-9 of the model's size)
// or above it by more than the tolerance plus that, or when its points are not on the surfaces'
// sphere or not the reported distance apart, or its certified interval misses the truth.
// Counted as the "surface_distance/sphere_zones" expectation.
TEST_P(Interface, SurfaceDistanceAnswersTheGapBetweenTwoSphereZones) {
  std::unique_ptr<BackendInstance> backend = createInstance(target());
  ASSERT_TRUE(backend);
  const Capabilities& caps = backend->capabilities();
  if (!caps.buildsShape(ShapeKind::kNurbsSurface) || !caps.queries.contains(QueryKind::kDistance)) {
    COLLIDO_KIT_SKIP(target().variant + " answers no distance queries between NURBS surfaces");
  }
  const nurbs::NurbsSurface zone_a = nurbs::sphereZone(Eigen::Vector3d::Zero(), 1.0, -45.0);
  const nurbs::NurbsSurface zone_b = nurbs::sphereZone(Eigen::Vector3d::Zero(), 1.0, 135.0);
  const BuildNeeds needs{QueryKindSet(QueryKind::kDistance)};
  Result<ModelHandle> a = backend->build(nurbs::viewOf(zone_a), needs);
  Result<ModelHandle> b = backend->build(nurbs::viewOf(zone_b), needs);
  ASSERT_TRUE(a.ok() && b.ok()) << (a.ok() ? b.status() : a.status()).toString();
  constexpr double kSize = 4.0;  // the scene's extent, about
  const double rounding = 1e-9 * kSize;
  Disagreement sum;
  std::string failures;
  QueryResult result;
  for (const auto& [abs_tolerance, rel_tolerance] : {std::pair{1e-7, 0.0}, std::pair{0.0, 1e-3}}) {
    for (const double gap : {0.75, 1e-4, 0.0, -0.3}) {
      const Pose pose_b = moved(2.0 + gap);
      const double truth = std::max(gap, 0.0);
      QueryRequest request;
      request.kind = QueryKind::kDistance;
      request.abs_tolerance = abs_tolerance;
      request.rel_tolerance = rel_tolerance;
      const Status s =
          backend->query(a.value(), Pose::Identity(), b.value(), pose_b, request, result);
      const DistanceResult& d = result.distance;
      const double allowed = std::max(abs_tolerance, rel_tolerance * truth) + rounding;
      const bool on_spheres =
          std::abs(d.point_a.norm() - 1.0) <= rounding &&
          std::abs((d.point_b - pose_b.translation()).norm() - 1.0) <= rounding &&
          std::abs((d.point_b - d.point_a).norm() - d.distance) <= rounding;
      const bool interval_holds =
          !d.lower || (*d.lower <= truth + rounding && *d.upper >= truth - rounding);
      if (!s.ok() || d.distance < truth - rounding || d.distance > truth + allowed || !on_spheres ||
          !interval_holds) {
        ++sum.disagreeing_frames;
        failures += " gap " + std::to_string(gap) + ": " +
                    (s.ok() ? "answered " + std::to_string(d.distance) : s.message()) + ";";
      }
    }
  }
  expectAsRecorded("surface_distance/sphere_zones", sum, failures);
}

// --- deformation -----------------------------------------------------------------------------

TEST_P(Interface, UpdateThenQueryAnswersForTheNewShape) {
  std::unique_ptr<BackendInstance> backend = createInstance(target());
  ASSERT_TRUE(backend);
  if (!backend->capabilities().buildsShape(ShapeKind::kTriangleMesh)) {
    COLLIDO_KIT_SKIP(target().variant + " builds no triangle meshes");
  }
  const Capabilities& caps = backend->capabilities();
  if (!caps.update) COLLIDO_KIT_SKIP(target().variant + " does not update models");
  const QueryKind kind =
      caps.queries.contains(QueryKind::kAllPairs) ? QueryKind::kAllPairs : QueryKind::kBoolean;
  if (!caps.queries.contains(kind)) COLLIDO_KIT_SKIP("answers neither boolean nor all_pairs");

  const TriangleMesh original = sphere(0.5, 24, 12);
  const TriangleMesh other = sphere(1.0, 24, 12);
  Result<ModelHandle> a = backend->build(original.view(), BuildNeeds{QueryKindSet(kind), true});
  Result<ModelHandle> b = backend->build(other.view(), BuildNeeds{QueryKindSet(kind)});
  ASSERT_TRUE(a.ok() && b.ok());
  // Apart before the update; the grown, moved sphere overlaps the other one after it.
  TriangleMesh grown = original;
  grown.vertices *= 2.2;
  grown.vertices.row(0).array() += 0.7;
  const Pose pose_b = moved(2.5);
  QueryRequest request;
  request.kind = kind;
  QueryResult result;
  ASSERT_TRUE(backend->query(a.value(), Pose::Identity(), b.value(), pose_b, request, result).ok());
  EXPECT_FALSE(result.intersecting) << "before the update the spheres are 1 apart";
  UpdateCounters work;
  work.counted = true;  // must be cleared by a backend that does not count
  ASSERT_TRUE(backend->update(a.value(), grown.vertices, &work).ok());
  EXPECT_EQ(work.counted, caps.counts_update_work);
  if (work.counted) {
    EXPECT_GT(work.nodes_refit + work.nodes_rebuilt, 0u) << "every vertex moved: nothing redone?";
    EXPECT_EQ(work.rebuilds == 0, work.nodes_rebuilt == 0) << "rebuilds without nodes, or back";
  }
  ASSERT_TRUE(backend->query(a.value(), Pose::Identity(), b.value(), pose_b, request, result).ok());
  const OracleAnswer truth = exactIntersectingPairs(grown, Pose::Identity(), other, pose_b);
  ASSERT_TRUE(truth.intersecting);

  FrameRecord record;
  compareWithOracle(grown, Pose::Identity(), other, pose_b, request, result, truth, record);
  const Disagreement d = disagreementOf(record, kind);
  expectAsRecorded(std::string("update/") + queryKindName(kind), d);
}

// --- answers against the oracle --------------------------------------------------------------

class SceneAnswers : public ::testing::TestWithParam<std::tuple<std::size_t, std::size_t>> {
 protected:
  const Target& target() const { return targets()[std::get<0>(GetParam())]; }
  const SceneCase& scene() const { return sceneCases()[std::get<1>(GetParam())]; }
  std::string viewCommand() const;
};

// The command whose page shows, frame by frame, the triangle pairs the backend and the oracle
// disagree on (docs/VIEW.md).
std::string SceneAnswers::viewCommand() const {
  if (scene().path.empty()) {
    return "this scene is one of the kit's own (tests/conformance/scene_cases.cpp); write it to "
           "a file and run collido view on it";
  }
  std::string backend = target().variant;
  if (!target().options.empty()) {
    backend += "[";
    bool first = true;
    for (const auto& [key, value] : target().options) {
      backend.append(first ? "" : ";").append(key).append("=").append(value);
      first = false;
    }
    backend += "]";
  }
  return "collido --plugin " + target().library->path() + " view " + scene().path +
         " --backends '" + backend + "' -o view.html";
}

TEST_P(SceneAnswers, MatchTheOracleOrTheRecordedExpectations) {
  Result<Expectations> expectations =
      loadExpectations(settings().expectations_dir, target().variant);
  ASSERT_TRUE(expectations.ok()) << expectations.status().message();
  const Status loaded = loadSceneCase(sceneCases()[std::get<1>(GetParam())]);
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  const BackendSpec spec{target().library, target().variant, target().options};
  RunOptions options;
  options.repetitions = 0;  // answers only; timing belongs to the study
  const RunReport report = runScene(*scene().scene, spec, options, *scene().oracle);
  ASSERT_TRUE(report.problems.empty()) << report.problems.front();
  int answered = 0;
  std::string skipped;
  std::string recorded;
  for (const QueryMeasurement& m : report.measurements) {
    if (m.status.skipped()) {
      skipped += (skipped.empty() ? "" : "; ") + m.query + " " + m.status.text();
      continue;
    }
    // Every query's failure is reported, not only the first one's.
    if (!m.ok()) {
      ADD_FAILURE() << m.query << ": " << m.status;
      continue;
    }
    ++answered;
    const std::string key = scene().name + "/" + m.query;
    const Disagreement measured = disagreementOf(m);
    if (!settings().write_expectations_dir.empty()) {
      ASSERT_TRUE(
          recordMeasurement(settings().write_expectations_dir, target().variant, key, measured)
              .ok());
    }
    const Disagreement expected = expectations.value().expectedFor(key);
    if (!expected.none()) recorded += m.query + " as recorded (" + expected.toString() + ") ";
    if (!(measured == expected))
      ADD_FAILURE()
          << key << ": measured " << measured.toString() << "\n  expected " << expected.toString()
          << " ("
          << (expectations.value().file.empty() ? "no expectations file: must be exact"
                                                : expectations.value().file)
          << ")\n  A comparator's changed count is a finding to review; update the file only "
             "after looking at the differing triangle pairs, frame by frame: "
          << viewCommand();
  }
  if (answered == 0) COLLIDO_KIT_SKIP("no query of this scene is answered: " + skipped);
  if (!recorded.empty() || !skipped.empty()) RecordProperty("detail", recorded + skipped);
}

std::string targetName(const ::testing::TestParamInfo<std::size_t>& info) {
  return targets()[info.param].test_name;
}

std::string targetSceneName(
    const ::testing::TestParamInfo<std::tuple<std::size_t, std::size_t>>& info) {
  return targets()[std::get<0>(info.param)].test_name + "__" +
         sceneCases()[std::get<1>(info.param)].test_name;
}

std::vector<std::size_t> indices(std::size_t n) {
  std::vector<std::size_t> out(n);
  for (std::size_t i = 0; i < n; ++i)
    out[i] = i;
  return out;
}

// The generators run when GoogleTest registers the tests, after main() filled the lists.
INSTANTIATE_TEST_SUITE_P(Plugin, Interface, ::testing::ValuesIn(indices(targets().size())),
                         targetName);
INSTANTIATE_TEST_SUITE_P(Plugin, SceneAnswers,
                         ::testing::Combine(::testing::ValuesIn(indices(targets().size())),
                                            ::testing::ValuesIn(indices(sceneCases().size()))),
                         targetSceneName);

}  // namespace
}  // namespace collido::conformance
