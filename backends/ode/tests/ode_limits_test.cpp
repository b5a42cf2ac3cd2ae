// What is particular to ODE and not covered by the conformance kit: dCollide's 16-bit contact
// capacity (65,536 aborts the process), the warnings ODE prints from inside dCollide, and
// OPCODE's crash on one-triangle meshes.
#include <cstdint>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include <collido/host/backend_instance.h>
#include <collido/host/plugin_library.h>
#include <collido/mesh/procedural.h>
#include <collido/ode/ode_backend.h>

extern "C" const CollidoPluginTable* collido_plugin_table_ode(void);

namespace collido::ode {
namespace {

std::unique_ptr<BackendInstance> makeOde() {
  Result<std::shared_ptr<PluginLibrary>> library =
      PluginLibrary::fromTable(collido_plugin_table_ode(), "ode (linked in)");
  EXPECT_TRUE(library.ok());
  Result<std::unique_ptr<BackendInstance>> instance =
      BackendInstance::create(library.value(), "ode");
  EXPECT_TRUE(instance.ok()) << (instance.ok() ? "" : instance.status().toString());
  return std::move(instance).value();
}

const BuildNeeds kNeeds{QueryKindSet(QueryKind::kBoolean) | QueryKind::kContacts, false};

// Two coplanar 100 x 100-cell sheets (20,000 triangles each), B shifted by half a cell in x and
// y: every triangle of A overlaps several of B, and ODE makes far more than 65,535 contacts
// (measured: the buffer fills at 65,535 with any capacity ODE accepts; about 0.4 million
// "hash table bucket overflow" warnings per call).
class DenseCoplanarSheets : public ::testing::Test {
 protected:
  void SetUp() override {
    GridSheetParams params;
    params.cells_x = 100;
    params.cells_y = 100;
    Result<TriangleMesh> sheet = makeGridSheet(params);
    ASSERT_TRUE(sheet.ok());
    mesh_ = std::move(sheet).value();
    ode_ = makeOde();
    a_ = ode_->build(mesh_.view(), kNeeds).value();
    b_ = ode_->build(mesh_.view(), kNeeds).value();
    pose_b_.translation() = Eigen::Vector3d(0.01, 0.01, 0.0);  // half a cell of 2 / 100
  }

  QueryResult contacts(std::uint64_t max_contacts) {
    QueryRequest request;
    request.kind = QueryKind::kContacts;
    request.max_contacts = max_contacts;
    QueryResult result;
    const Status status = ode_->query(a_, Pose::Identity(), b_, pose_b_, request, result);
    EXPECT_TRUE(status.ok()) << status.toString();
    return result;
  }

  TriangleMesh mesh_;
  std::unique_ptr<BackendInstance> ode_;
  ModelHandle a_ = 0;
  ModelHandle b_ = 0;
  Pose pose_b_ = Pose::Identity();
};

TEST_F(DenseCoplanarSheets, CapabilitiesDeclareTheCap) {
  EXPECT_EQ(ode_->capabilities().max_contacts, kMaxContactsPerCall);
  EXPECT_EQ(kMaxContactsPerCall, 65535u);
}

TEST_F(DenseCoplanarSheets, NoLimitStopsAtTheCapAndSaysSo) {
  const QueryResult result = contacts(0);
  EXPECT_TRUE(result.intersecting);
  EXPECT_EQ(result.contacts.size(), kMaxContactsPerCall);
  EXPECT_TRUE(result.truncated);
}

// 65,536 in dCollide's flags reads as a capacity of 0: ODE fails a user assertion and aborts.
// The plugin must clamp any larger request to the cap; reaching the end of this test is the check.
TEST_F(DenseCoplanarSheets, RequestsAboveTheCapAreClampedNotPassedOn) {
  for (const std::uint64_t asked : {kMaxContactsPerCall, kMaxContactsPerCall + 1,
                                    std::uint64_t{1} << 20, std::uint64_t{1} << 40}) {
    const QueryResult result = contacts(asked);
    EXPECT_EQ(result.contacts.size(), kMaxContactsPerCall) << "max_contacts " << asked;
    EXPECT_TRUE(result.truncated) << "max_contacts " << asked;
  }
}

TEST_F(DenseCoplanarSheets, SmallLimitsAreExactAndTruncated) {
  for (const std::uint64_t asked : {1u, 7u, 1000u, 65534u}) {
    const QueryResult result = contacts(asked);
    EXPECT_EQ(result.contacts.size(), asked);
    EXPECT_TRUE(result.truncated) << "max_contacts " << asked;
  }
}

TEST_F(DenseCoplanarSheets, WarningsAreCountedNotPrinted) {
  const std::uint64_t before = odeMessagesOnThisThread();
  ::testing::internal::CaptureStderr();
  (void)contacts(0);
  const std::string printed = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(printed, "");
  EXPECT_GT(odeMessagesOnThisThread(), before);
  EXPECT_NE(std::string(lastOdeMessageFormat()).find("bucket overflow"), std::string::npos)
      << lastOdeMessageFormat();
}

// Below the limit nothing is truncated: one contact slot more than the limit tells.
TEST(OdeContacts, FewContactsAreNotTruncated) {
  std::unique_ptr<BackendInstance> ode = makeOde();
  SphereParams params;
  const TriangleMesh sphere = makeSphere(params).value();
  const ModelHandle a = ode->build(sphere.view(), kNeeds).value();
  const ModelHandle b = ode->build(sphere.view(), kNeeds).value();
  Pose pose_b = Pose::Identity();
  pose_b.translation() = Eigen::Vector3d(1.9, 0.0, 0.0);
  QueryRequest request;
  request.kind = QueryKind::kContacts;
  QueryResult all;
  ASSERT_TRUE(ode->query(a, Pose::Identity(), b, pose_b, request, all).ok());
  ASSERT_TRUE(all.intersecting);
  ASSERT_GT(all.contacts.size(), 1u);
  EXPECT_FALSE(all.truncated);
  request.max_contacts = all.contacts.size();
  QueryResult exact;
  ASSERT_TRUE(ode->query(a, Pose::Identity(), b, pose_b, request, exact).ok());
  EXPECT_EQ(exact.contacts.size(), all.contacts.size());
  EXPECT_FALSE(exact.truncated);
  // The normal points from A towards B (ODE's points into its first geom).
  for (const Contact& c : all.contacts)
    EXPECT_GT(c.normal.x(), 0.0);
}

// OPCODE builds no tree node for a single triangle and its collider crashes on it; the plugin
// gives such a mesh its triangle twice and reports the copy as triangle 0.
TEST(OdeSingleTriangle, CrossingTrianglesAreFoundWithoutCrashing) {
  std::unique_ptr<BackendInstance> ode = makeOde();
  Eigen::Matrix3Xd vertices(3, 3);
  vertices << 0, 1, 0,  //
      0, 0, 1,          //
      0, 0, 0;
  Eigen::Matrix3Xi triangles(3, 1);
  triangles << 0, 1, 2;
  const MeshView view{Eigen::Map<const Eigen::Matrix3Xd>(vertices.data(), 3, 3),
                      Eigen::Map<const Eigen::Matrix3Xi>(triangles.data(), 3, 1)};
  const ModelHandle a = ode->build(view, kNeeds).value();
  const ModelHandle b = ode->build(view, kNeeds).value();
  // B stands upright through A: turned 90 degrees about x, moved into A's interior.
  Pose pose_b(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  pose_b.translation() = Eigen::Vector3d(0.1, 0.3, -0.5);
  QueryRequest request;
  request.kind = QueryKind::kContacts;
  QueryResult result;
  ASSERT_TRUE(ode->query(a, Pose::Identity(), b, pose_b, request, result).ok());
  EXPECT_TRUE(result.intersecting);
  for (const Contact& c : result.contacts) {
    EXPECT_EQ(c.triangle_a, 0);
    EXPECT_EQ(c.triangle_b, 0);
  }
}

}  // namespace
}  // namespace collido::ode
