// Plugin loading and the adapter's checks, one test per case.
//
// Loading goes through real files: the obbtree plugin from the build's plugins/ folder, and two
// test-only libraries (tests/bad_input/plugins/) built into their own folder: one whose table
// claims another interface version, one without the entry point. The adapter's checks go through
// the obbtree table linked into this executable (collido_plugin_table_obbtree), the way static
// test builds reach a plugin. The comment above each test shows the message users get.
#include <collido/host/backend_instance.h>
#include <collido/host/plugin_library.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bad_input/rejection.h"
#include "support/test_paths.h"

extern "C" const CollidoPluginTable* collido_plugin_table_obbtree(void);

namespace collido {
namespace {

using test::hasCodeAndWords;
using test::rejected;

std::string realPluginPath() {
  return test::pluginDirectory() + "/libcollido_plugin_obbtree.so";
}
std::string testPluginPath(const std::string& name) {
  return std::string(COLLIDO_TEST_PLUGIN_DIR) + "/lib" + name + ".so";
}

const std::string kAbi = std::to_string(COLLIDO_PLUGIN_ABI_VERSION);
const std::string kOtherAbi = std::to_string(COLLIDO_PLUGIN_ABI_VERSION + 1u);

// ---- loading files ---------------------------------------------------------------------------

TEST(PluginLoading, RealPluginLoadsAndAnswers) {
  Result<std::shared_ptr<PluginLibrary>> library = PluginLibrary::open(realPluginPath());
  ASSERT_TRUE(library.ok()) << library.status().toString();
  const PluginLibrary& plugin = *library.value();
  EXPECT_EQ(plugin.path(), realPluginPath());
  EXPECT_EQ(plugin.table().abi_version, COLLIDO_PLUGIN_ABI_VERSION);
  EXPECT_EQ(plugin.table().struct_size, sizeof(CollidoPluginTable));
  EXPECT_EQ(plugin.name(), "obbtree");
  ASSERT_EQ(plugin.variants().size(), 1u);
  EXPECT_EQ(plugin.variants()[0].name, "obbtree");
  EXPECT_TRUE(plugin.hasVariant("obbtree"));

  // And it works through dlopen: two unit triangles crossing each other.
  Result<std::unique_ptr<BackendInstance>> instance =
      BackendInstance::create(library.value(), "obbtree");
  ASSERT_TRUE(instance.ok()) << instance.status().toString();
  Eigen::Matrix3Xd vertices(3, 3);
  vertices << 0, 1, 0, 0, 0, 1, 0, 0, 0;
  Eigen::Matrix3Xi triangles(3, 1);
  triangles << 0, 1, 2;
  const MeshView mesh{Eigen::Map<const Eigen::Matrix3Xd>(vertices.data(), 3, 3),
                      Eigen::Map<const Eigen::Matrix3Xi>(triangles.data(), 3, 1)};
  Result<ModelHandle> model = instance.value()->build(mesh, BuildNeeds{QueryKind::kBoolean, false});
  ASSERT_TRUE(model.ok()) << model.status().toString();
  Pose turned = Pose::Identity();
  turned.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  turned.translation() = Eigen::Vector3d(0.25, 0.25, -0.5);
  QueryResult result;
  ASSERT_TRUE(instance.value()
                  ->query(model.value(), Pose::Identity(), model.value(), turned,
                          QueryRequest{QueryKind::kBoolean, 0, 0}, result)
                  .ok());
  EXPECT_TRUE(result.intersecting);
}

// "plugin <dir>/libwrong_abi_plugin.so: built for plugin interface version 2, but this
//  Collidoscope uses version 1; rebuild the plugin against this Collidoscope"
TEST(PluginLoading, AnotherInterfaceVersionIsRefused) {
  const std::string path = testPluginPath("wrong_abi_plugin");
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  EXPECT_TRUE(rejected(PluginLibrary::open(path),
                       {path, "interface version " + kOtherAbi, "uses version " + kAbi}));
}

// "plugin <dir>/libno_entry_plugin.so: not a Collidoscope plugin: no 'collido_plugin_table' entry
//  point"
TEST(PluginLoading, LibraryWithoutEntryPointIsRefused) {
  const std::string path = testPluginPath("no_entry_plugin");
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  EXPECT_TRUE(rejected(PluginLibrary::open(path),
                       {path, "not a Collidoscope plugin", COLLIDO_PLUGIN_ENTRY_SYMBOL}));
}

// "plugin <dir>/libcollido_plugin_fake.so: cannot load it as a shared library: <dir>/...: invalid
//  ELF header"
TEST(PluginLoading, FileThatIsNotASharedLibraryIsRefused) {
  const std::string path = test::makeTempDirectory("bad_plugin") + "/libcollido_plugin_fake.so";
  test::writeFile(path, "this is text, not an ELF file\n");
  EXPECT_TRUE(rejected(PluginLibrary::open(path), {path, "cannot load it as a shared library"}));
}

// "plugin <dir>/libcollido_plugin_absent.so: file not found"
TEST(PluginLoading, MissingFileIsRefused) {
  const std::string path = test::makeTempDirectory("bad_plugin") + "/libcollido_plugin_absent.so";
  EXPECT_TRUE(rejected(PluginLibrary::open(path), {path, "file not found"}));
}

// "plugin <dir>: cannot load it as a shared library: ...: cannot read file data: Is a directory"
TEST(PluginLoading, DirectoryIsRefused) {
  const std::string path = test::makeTempDirectory("bad_plugin");
  EXPECT_TRUE(rejected(PluginLibrary::open(path), {path, "cannot load"}));
}

// ---- the table's own checks (linked-in tables) -----------------------------------------------

/// A copy of the obbtree table, to break one field at a time.
CollidoPluginTable obbtreeTable() {
  return *collido_plugin_table_obbtree();
}

// "plugin future table: built for plugin interface version 2, but this Collidoscope uses
//  version 1; ..."
TEST(PluginLoading, LinkedTableOfAnotherInterfaceVersionIsRefused) {
  CollidoPluginTable table = obbtreeTable();
  table.abi_version = COLLIDO_PLUGIN_ABI_VERSION + 1u;
  EXPECT_TRUE(rejected(PluginLibrary::fromTable(&table, "future table"),
                       {"future table", "version " + kOtherAbi, "version " + kAbi}));
}

// "plugin null table: the entry point returned no table"
TEST(PluginLoading, NullTableIsRefused) {
  EXPECT_TRUE(
      rejected(PluginLibrary::fromTable(nullptr, "null table"), {"null table", "no table"}));
}

// "plugin short table: table is 8 bytes, expected 120"
TEST(PluginLoading, TooSmallTableIsRefused) {
  CollidoPluginTable table = obbtreeTable();
  table.struct_size = 8;
  EXPECT_TRUE(rejected(PluginLibrary::fromTable(&table, "short table"),
                       {"short table", "8 bytes", std::to_string(sizeof(CollidoPluginTable))}));
}

// "plugin nameless: the table has no plugin name"
TEST(PluginLoading, TableWithoutNameIsRefused) {
  CollidoPluginTable table = obbtreeTable();
  table.plugin_name = "";
  EXPECT_TRUE(
      rejected(PluginLibrary::fromTable(&table, "nameless"), {"nameless", "no plugin name"}));
}

// "plugin no variants: the table lists no variants"
TEST(PluginLoading, TableWithoutVariantsIsRefused) {
  CollidoPluginTable table = obbtreeTable();
  table.variant_count = 0;
  EXPECT_TRUE(rejected(PluginLibrary::fromTable(&table, "no variants"),
                       {"no variants", "lists no variants"}));
}

// "plugin no query: the table is missing a function"
TEST(PluginLoading, TableMissingAFunctionIsRefused) {
  CollidoPluginTable table = obbtreeTable();
  table.query = nullptr;
  EXPECT_TRUE(
      rejected(PluginLibrary::fromTable(&table, "no query"), {"no query", "missing a function"}));
}

// ---- discovery -------------------------------------------------------------------------------

std::size_t countContaining(const std::vector<std::string>& problems, const std::string& text) {
  return static_cast<std::size_t>(
      std::count_if(problems.begin(), problems.end(),
                    [&](const std::string& p) { return p.find(text) != std::string::npos; }));
}

// Every bad path becomes a recorded problem naming its file; the good plugin still loads.
TEST(PluginLoading, DiscoveryRecordsProblemsInsteadOfFailing) {
  const std::string folder = test::makeTempDirectory("bad_plugin_folder");
  test::writeFile(folder + "/libcollido_plugin_fake.so", "not a library");
  test::writeFile(folder + "/readme.txt", "not a plugin name, so not even tried");
  const std::string missing = folder + "/libcollido_plugin_absent.so";
  const PluginDiscovery found =
      discoverPlugins({testPluginPath("wrong_abi_plugin"), testPluginPath("no_entry_plugin"),
                       missing, folder, test::pluginDirectory() + "/libcollido_plugin_obbtree.so"},
                      /*use_defaults=*/false);
  ASSERT_EQ(found.plugins.size(), 1u);
  EXPECT_EQ(found.plugins[0]->name(), "obbtree");
  EXPECT_EQ(found.problems.size(), 4u) << ::testing::PrintToString(found.problems);
  EXPECT_EQ(countContaining(found.problems, testPluginPath("wrong_abi_plugin") + ":"), 1u);
  EXPECT_EQ(countContaining(found.problems, testPluginPath("no_entry_plugin") + ":"), 1u);
  EXPECT_EQ(countContaining(found.problems, missing + ": file not found"), 1u);
  EXPECT_EQ(countContaining(found.problems, folder + "/libcollido_plugin_fake.so:"), 1u);
  EXPECT_EQ(countContaining(found.problems, "readme.txt"), 0u);
}

// A second plugin offering a variant already loaded is ignored, and the problem says so:
// "plugin <dir>/libcollido_plugin_copy.so: variant 'obbtree' is already provided by an earlier
//  plugin; this one is ignored"
TEST(PluginLoading, DiscoveryRecordsAShadowedVariant) {
  const std::string copy =
      test::makeTempDirectory("bad_plugin_copy") + "/libcollido_plugin_copy.so";
  std::filesystem::copy_file(realPluginPath(), copy);
  const PluginDiscovery found = discoverPlugins({realPluginPath(), copy}, false);
  ASSERT_EQ(found.plugins.size(), 1u);
  EXPECT_EQ(found.plugins[0]->path(), realPluginPath());
  ASSERT_EQ(found.problems.size(), 1u);
  EXPECT_NE(found.problems[0].find(copy), std::string::npos) << found.problems[0];
  EXPECT_NE(found.problems[0].find("'obbtree' is already provided"), std::string::npos)
      << found.problems[0];
}

// ---- the adapter: creating instances ---------------------------------------------------------

std::shared_ptr<PluginLibrary> staticObbtree() {
  Result<std::shared_ptr<PluginLibrary>> library =
      PluginLibrary::fromTable(collido_plugin_table_obbtree(), "obbtree (static)");
  if (!library.ok()) {
    ADD_FAILURE() << library.status().toString();
    return nullptr;
  }
  return library.value();
}

Result<std::unique_ptr<BackendInstance>> createObbtree(
    const std::map<std::string, std::string>& options = {}) {
  return BackendInstance::create(staticObbtree(), "obbtree", options);
}

TEST(PluginLoading, StaticTableLoads) {
  const std::shared_ptr<PluginLibrary> library = staticObbtree();
  ASSERT_NE(library, nullptr);
  EXPECT_EQ(library->path(), "obbtree (static)");
  EXPECT_EQ(library->name(), "obbtree");
  EXPECT_TRUE(library->hasVariant("obbtree"));
  Result<std::unique_ptr<BackendInstance>> instance = createObbtree({{"max_leaf_triangles", "4"}});
  ASSERT_TRUE(instance.ok()) << instance.status().toString();
  EXPECT_EQ(instance.value()->name(), "obbtree");
  EXPECT_TRUE(instance.value()->capabilities().queries.contains(QueryKind::kAllPairs));
  EXPECT_TRUE(instance.value()->capabilities().queries.contains(QueryKind::kContacts));
}

// The host checks the variant before calling the plugin:
// "plugin obbtree (static) has no variant 'obbtree:fast'"
TEST(PluginLoading, UnknownVariantIsRefusedByTheHost) {
  EXPECT_TRUE(rejected(BackendInstance::create(staticObbtree(), "obbtree:fast"),
                       {"obbtree (static)", "no variant 'obbtree:fast'"}));
}

// And the adapter checks it again for callers of the C table:
// "plugin obbtree has no variant 'obbtree:fast'"
TEST(PluginLoading, UnknownVariantIsRefusedByTheAdapter) {
  const CollidoPluginTable& table = *collido_plugin_table_obbtree();
  CollidoMessage message{};
  CollidoInstance* instance = nullptr;
  const std::int32_t code = table.create("obbtree:fast", nullptr, 0, &instance, &message);
  EXPECT_EQ(code, COLLIDO_STATUS_INVALID_ARGUMENT);
  EXPECT_EQ(instance, nullptr);
  EXPECT_NE(std::string(message.text).find("no variant 'obbtree:fast'"), std::string::npos)
      << message.text;
}

// A misspelt option is an error naming it, not a silently ignored default:
// "obbtree: unknown option(s): max_leaf_triangle (known: max_leaf_triangles)"
TEST(PluginLoading, UnknownOptionIsRefused) {
  EXPECT_TRUE(rejected(createObbtree({{"max_leaf_triangle", "3"}}),
                       {"obbtree", "unknown option", "max_leaf_triangle", "max_leaf_triangles"}));
}

// "obbtree: option max_leaf_triangles = 'few': expected an integer in [1, 65535]"
TEST(PluginLoading, UnparseableOptionValueIsRefused) {
  EXPECT_TRUE(rejected(createObbtree({{"max_leaf_triangles", "few"}}),
                       {"obbtree", "max_leaf_triangles = 'few'", "expected an integer"}));
}

// "obbtree: option max_leaf_triangles = '0': expected an integer in [1, 65535]"
TEST(PluginLoading, OutOfRangeOptionValueIsRefused) {
  EXPECT_TRUE(rejected(createObbtree({{"max_leaf_triangles", "0"}}),
                       {"obbtree", "max_leaf_triangles = '0'", "[1, 65535]"}));
}

// "obbtree: option max_leaf_triangles = '4x': expected an integer in [1, 65535]"
TEST(PluginLoading, OptionValueWithTrailingTextIsRefused) {
  EXPECT_TRUE(rejected(createObbtree({{"max_leaf_triangles", "4x"}}),
                       {"obbtree", "max_leaf_triangles = '4x'"}));
}

// ---- the adapter: building -------------------------------------------------------------------

/// A mesh owned by the test, viewed for build().
struct OwnedMesh {
  Eigen::Matrix3Xd vertices;
  Eigen::Matrix3Xi triangles;
  MeshView view() const {
    return MeshView{Eigen::Map<const Eigen::Matrix3Xd>(vertices.data(), 3, vertices.cols()),
                    Eigen::Map<const Eigen::Matrix3Xi>(triangles.data(), 3, triangles.cols())};
  }
};

/// A unit tetrahedron, outward-facing.
OwnedMesh tetrahedron() {
  OwnedMesh mesh;
  mesh.vertices.resize(3, 4);
  mesh.vertices << 0, 1, 0, 0,  //
      0, 0, 1, 0,               //
      0, 0, 0, 1;
  mesh.triangles.resize(3, 4);
  mesh.triangles << 0, 0, 0, 1,  //
      2, 1, 3, 2,                //
      1, 3, 2, 3;
  return mesh;
}

const BuildNeeds kBoolean{QueryKind::kBoolean, false};
const BuildNeeds kDeforming{QueryKind::kBoolean, true};

/// The instance every adapter test uses; fails the test when it cannot be created.
std::unique_ptr<BackendInstance> instance() {
  Result<std::unique_ptr<BackendInstance>> created = createObbtree();
  if (!created.ok()) {
    ADD_FAILURE() << created.status().toString();
    return nullptr;
  }
  return std::move(created).value();
}

// "obbtree: build: mesh is empty (0 vertices, 0 triangles)"
TEST(PluginLoading, EmptyMeshIsRefused) {
  auto backend = instance();
  ASSERT_NE(backend, nullptr);
  const OwnedMesh empty;
  EXPECT_TRUE(rejected(backend->build(empty.view(), kBoolean), {"obbtree", "build", "empty"}));
}

// "obbtree: build: mesh is empty (4 vertices, 0 triangles)"
TEST(PluginLoading, MeshWithoutTrianglesIsRefused) {
  auto backend = instance();
  ASSERT_NE(backend, nullptr);
  OwnedMesh mesh = tetrahedron();
  mesh.triangles.resize(3, 0);
  EXPECT_TRUE(rejected(backend->build(mesh.view(), kBoolean), {"obbtree", "0 triangles"}));
}

// "obbtree: build: vertex 2 has a non-finite coordinate"
TEST(PluginLoading, NanVertexIsRefused) {
  auto backend = instance();
  ASSERT_NE(backend, nullptr);
  OwnedMesh mesh = tetrahedron();
  mesh.vertices(1, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(
      rejected(backend->build(mesh.view(), kBoolean), {"obbtree", "vertex 2", "non-finite"}));
}

// "obbtree: build: vertex 3 has a non-finite coordinate"
TEST(PluginLoading, InfiniteVertexIsRefused) {
  auto backend = instance();
  ASSERT_NE(backend, nullptr);
  OwnedMesh mesh = tetrahedron();
  mesh.vertices(0, 3) = -std::numeric_limits<double>::infinity();
  EXPECT_TRUE(
      rejected(backend->build(mesh.view(), kBoolean), {"obbtree", "vertex 3", "non-finite"}));
}

// "obbtree: build: triangle 3 references vertex 4 of 4"
TEST(PluginLoading, OutOfRangeIndexIsRefused) {
  auto backend = instance();
  ASSERT_NE(backend, nullptr);
  OwnedMesh mesh = tetrahedron();
  mesh.triangles(2, 3) = 4;
  EXPECT_TRUE(rejected(backend->build(mesh.view(), kBoolean),
                       {"obbtree", "triangle 3", "references vertex 4"}));
}

// "obbtree: build: triangle 1 references vertex -1 of 4"
TEST(PluginLoading, NegativeIndexIsRefused) {
  auto backend = instance();
  ASSERT_NE(backend, nullptr);
  OwnedMesh mesh = tetrahedron();
  mesh.triangles(0, 1) = -1;
  EXPECT_TRUE(rejected(backend->build(mesh.view(), kBoolean),
                       {"obbtree", "triangle 1", "references vertex -1"}));
}

// ---- the adapter: queries --------------------------------------------------------------------

/// An instance with one tetrahedron built for boolean queries only.
struct Built {
  std::unique_ptr<BackendInstance> backend;
  ModelHandle model = 0;
};

Built builtTetrahedron(const BuildNeeds& needs = kBoolean) {
  Built out;
  out.backend = instance();
  if (!out.backend) return out;
  const OwnedMesh mesh = tetrahedron();
  Result<ModelHandle> model = out.backend->build(mesh.view(), needs);
  if (!model.ok()) {
    ADD_FAILURE() << model.status().toString();
    return out;
  }
  out.model = model.value();
  return out;
}

Status queryOf(Built& built, ModelHandle a, ModelHandle b, QueryKind kind,
               const Pose& pose_b = Pose::Identity()) {
  QueryResult result;
  return built.backend->query(a, Pose::Identity(), b, pose_b, QueryRequest{kind, 0, 0}, result);
}

TEST(PluginLoading, ValidQuerySucceeds) {
  Built built = builtTetrahedron();
  ASSERT_NE(built.model, 0u);
  QueryResult result;
  const Status s = built.backend->query(built.model, Pose::Identity(), built.model,
                                        Pose::Identity(), QueryRequest{}, result);
  ASSERT_TRUE(s.ok()) << s.toString();
  EXPECT_TRUE(result.intersecting);
}

// A model built for boolean queries, asked for all pairs:
// "obbtree: query: model handle 1/1 was built for boolean, not all_pairs"
TEST(PluginLoading, QueryKindTheModelWasNotBuiltForIsInvalid) {
  Built built = builtTetrahedron();
  ASSERT_NE(built.model, 0u);
  EXPECT_TRUE(rejected(queryOf(built, built.model, built.model, QueryKind::kAllPairs),
                       {"obbtree", "built for boolean", "not all_pairs"}));
}

// "obbtree: does not answer contacts queries"
// The obbtree answers every kind: a model asked a kind it was not built for is refused.
TEST(PluginLoading, QueryKindTheModelWasNotBuiltForIsRefused) {
  Built built = builtTetrahedron();
  ASSERT_NE(built.model, 0u);
  EXPECT_TRUE(hasCodeAndWords(queryOf(built, built.model, built.model, QueryKind::kContacts),
                              StatusCode::kInvalidArgument, {"obbtree", "built for", "contacts"}));
}

// "obbtree: query: distance tolerances must be finite and >= 0 (absolute -1.000000, ...)"
TEST(PluginLoading, NegativeOrNonFiniteDistanceToleranceIsInvalid) {
  Built built = builtTetrahedron(BuildNeeds{QueryKindSet(QueryKind::kDistance)});
  ASSERT_NE(built.model, 0u);
  for (const auto& [abs_tolerance, rel_tolerance] :
       {std::pair{-1.0, 0.0}, std::pair{0.0, std::numeric_limits<double>::quiet_NaN()},
        std::pair{std::numeric_limits<double>::infinity(), 0.0}}) {
    QueryRequest request{QueryKind::kDistance, 0, 0, abs_tolerance, rel_tolerance};
    QueryResult result;
    EXPECT_TRUE(rejected(built.backend->query(built.model, Pose::Identity(), built.model,
                                              Pose::Identity(), request, result),
                         {"obbtree", "distance tolerances must be finite and >= 0"}));
  }
}

// A first contact asked with a bad end of its step, or a bracket width at or below zero:
// "obbtree: query: end pose of B: pose has a non-finite entry",
// "obbtree: query: end pose of A: not a rotation (...)",
// "obbtree: query: the bracket width must be finite and > 0, not 0.000000"
TEST(PluginLoading, AFirstContactWithABadStepIsInvalid) {
  Built built = builtTetrahedron(BuildNeeds{QueryKindSet(QueryKind::kFirstContact)});
  ASSERT_NE(built.model, 0u);
  const auto ask = [&](const QueryRequest& request) {
    QueryResult result;
    return built.backend->query(built.model, Pose::Identity(), built.model, Pose::Identity(),
                                request, result);
  };
  QueryRequest request;
  request.kind = QueryKind::kFirstContact;
  request.step = StepEnd{Pose::Identity(), Pose::Identity(), 1e-3};
  ASSERT_TRUE(ask(request).ok());
  QueryRequest not_finite = request;
  not_finite.step->pose_b.translation().y() = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(rejected(ask(not_finite), {"obbtree", "end pose of B", "non-finite"}));
  QueryRequest sheared = request;
  sheared.step->pose_a.linear()(0, 1) = 0.5;
  EXPECT_TRUE(rejected(ask(sheared), {"obbtree", "end pose of A", "not a rotation"}));
  for (const double width : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    QueryRequest bad_width = request;
    bad_width.step->bracket_width = width;
    EXPECT_TRUE(rejected(ask(bad_width), {"obbtree", "bracket width must be finite and > 0"}));
  }
}

// A request must name exactly one kind: "obbtree: query: kind 3 is not one kind"
TEST(PluginLoading, QueryOfTwoKindsAtOnceIsInvalid) {
  const CollidoPluginTable& table = *collido_plugin_table_obbtree();
  CollidoInstance* raw = nullptr;
  CollidoMessage message{};
  ASSERT_EQ(table.create("obbtree", nullptr, 0, &raw, &message), COLLIDO_STATUS_OK) << message.text;
  CollidoPose identity{{1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 0}};
  CollidoQueryRequest request{};
  request.kind = COLLIDO_QUERY_BOOLEAN | COLLIDO_QUERY_ALL_PAIRS;
  CollidoQueryResult result{};
  const std::int32_t code =
      table.query(raw, 1, &identity, 1, &identity, &request, &result, &message);
  table.destroy(raw);
  EXPECT_EQ(code, COLLIDO_STATUS_INVALID_ARGUMENT);
  EXPECT_NE(std::string(message.text).find("not one kind"), std::string::npos) << message.text;
}

// "obbtree: query: pose of B: not a rotation (|R^T R - I| = 5.196152, det = 8.000000; a pose must
//  be rigid: orthonormal, determinant +1)"
TEST(PluginLoading, ScaledPoseIsRefused) {
  Built built = builtTetrahedron();
  ASSERT_NE(built.model, 0u);
  Pose scaled = Pose::Identity();
  scaled.linear() *= 2.0;
  EXPECT_TRUE(rejected(queryOf(built, built.model, built.model, QueryKind::kBoolean, scaled),
                       {"obbtree", "pose of B", "not a rotation"}));
}

// A reflection is orthonormal but not a rotation:
// "obbtree: query: pose of B: not a rotation (|R^T R - I| = 0.000000, det = -1.000000; ...)"
TEST(PluginLoading, ReflectedPoseIsRefused) {
  Built built = builtTetrahedron();
  ASSERT_NE(built.model, 0u);
  Pose mirrored = Pose::Identity();
  mirrored.linear()(2, 2) = -1.0;
  EXPECT_TRUE(rejected(queryOf(built, built.model, built.model, QueryKind::kBoolean, mirrored),
                       {"obbtree", "pose of B", "not a rotation", "det = -1"}));
}

// "obbtree: query: pose of B: pose has a non-finite entry"
TEST(PluginLoading, NonFinitePoseIsRefused) {
  Built built = builtTetrahedron();
  ASSERT_NE(built.model, 0u);
  Pose pose = Pose::Identity();
  pose.translation().x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(rejected(queryOf(built, built.model, built.model, QueryKind::kBoolean, pose),
                       {"obbtree", "pose of B", "non-finite"}));
}

// ---- the adapter: handles --------------------------------------------------------------------

// "obbtree: query: model handle 1/1 is not a live model"
TEST(PluginLoading, StaleHandleAfterReleaseIsInvalid) {
  Built built = builtTetrahedron();
  ASSERT_NE(built.model, 0u);
  ASSERT_TRUE(built.backend->release(built.model).ok());
  EXPECT_TRUE(hasCodeAndWords(queryOf(built, built.model, built.model, QueryKind::kBoolean),
                              StatusCode::kInvalidHandle, {"obbtree", "not a live model"}));
  EXPECT_TRUE(hasCodeAndWords(built.backend->memory(built.model), StatusCode::kInvalidHandle,
                              {"memory", "not a live model"}));
  EXPECT_TRUE(hasCodeAndWords(built.backend->release(built.model), StatusCode::kInvalidHandle,
                              {"release", "not a live model"}));
}

// The slot is reused by the next build, with a new generation: the old handle stays stale.
TEST(PluginLoading, StaleHandleStaysInvalidWhenItsSlotIsReused) {
  Built built = builtTetrahedron();
  ASSERT_NE(built.model, 0u);
  ASSERT_TRUE(built.backend->release(built.model).ok());
  const OwnedMesh mesh = tetrahedron();
  Result<ModelHandle> fresh = built.backend->build(mesh.view(), kBoolean);
  ASSERT_TRUE(fresh.ok()) << fresh.status().toString();
  EXPECT_NE(fresh.value(), built.model);
  EXPECT_TRUE(queryOf(built, fresh.value(), fresh.value(), QueryKind::kBoolean).ok());
  EXPECT_TRUE(hasCodeAndWords(queryOf(built, built.model, fresh.value(), QueryKind::kBoolean),
                              StatusCode::kInvalidHandle, {"not a live model"}));
}

// 0 is never valid, and neither is a handle no build returned.
TEST(PluginLoading, NeverIssuedHandleIsInvalid) {
  Built built = builtTetrahedron();
  ASSERT_NE(built.model, 0u);
  for (const ModelHandle bogus :
       {ModelHandle{0}, built.model + 1, built.model + (ModelHandle{1} << 32), ~ModelHandle{0}}) {
    EXPECT_TRUE(hasCodeAndWords(queryOf(built, built.model, bogus, QueryKind::kBoolean),
                                StatusCode::kInvalidHandle, {"not a live model"}))
        << bogus;
    EXPECT_TRUE(hasCodeAndWords(built.backend->memory(bogus), StatusCode::kInvalidHandle,
                                {"not a live model"}))
        << bogus;
  }
}

// ---- the adapter: updates --------------------------------------------------------------------

// "obbtree: update: the model was built rigid (needs did not say it deforms)"
TEST(PluginLoading, UpdateOfARigidModelIsRefused) {
  Built built = builtTetrahedron(kBoolean);
  ASSERT_NE(built.model, 0u);
  EXPECT_TRUE(rejected(built.backend->update(built.model, tetrahedron().vertices),
                       {"obbtree", "update", "rigid"}));
}

// "obbtree: update: 3 positions for a model with 4 vertices"
TEST(PluginLoading, UpdateWithTheWrongVertexCountIsRefused) {
  Built built = builtTetrahedron(kDeforming);
  ASSERT_NE(built.model, 0u);
  const Eigen::Matrix3Xd three = tetrahedron().vertices.leftCols(3);
  EXPECT_TRUE(rejected(built.backend->update(built.model, three),
                       {"obbtree", "update", "3 positions", "4 vertices"}));
}

// "obbtree: update: vertex 0 has a non-finite coordinate"
TEST(PluginLoading, UpdateWithANanPositionIsRefused) {
  Built built = builtTetrahedron(kDeforming);
  ASSERT_NE(built.model, 0u);
  Eigen::Matrix3Xd moved = tetrahedron().vertices;
  moved(2, 0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(rejected(built.backend->update(built.model, moved),
                       {"obbtree", "update", "vertex 0", "non-finite"}));
}

// "obbtree: update: model handle 1/1 is not a live model"
TEST(PluginLoading, UpdateOfAReleasedModelIsInvalidHandle) {
  Built built = builtTetrahedron(kDeforming);
  ASSERT_NE(built.model, 0u);
  ASSERT_TRUE(built.backend->update(built.model, tetrahedron().vertices).ok());
  ASSERT_TRUE(built.backend->release(built.model).ok());
  EXPECT_TRUE(hasCodeAndWords(built.backend->update(built.model, tetrahedron().vertices),
                              StatusCode::kInvalidHandle, {"update", "not a live model"}));
}

}  // namespace
}  // namespace collido
