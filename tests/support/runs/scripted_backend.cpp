#include "support/runs/scripted_backend.h"

#include <optional>
#include <string>

#include <gtest/gtest.h>

#include <collido/plugin_export.h>

namespace collido::test {
namespace {

class ScriptedModel final : public BackendModel {
 public:
  std::size_t memoryBytes() const override { return sizeof(*this); }
};

// Counts one kind of call and fails the scripted one (0: none).
class ScriptedCall {
 public:
  ScriptedCall(const char* kind, std::int64_t failing) : kind_(kind), failing_(failing) {}

  Status next() {
    ++calls_;
    if (calls_ != failing_) return {};
    return Status(StatusCode::kEngineFailure,
                  "scripted failure of " + std::string(kind_) + " call " + std::to_string(calls_));
  }

 private:
  const char* kind_;
  std::int64_t failing_;
  std::int64_t calls_ = 0;
};

class ScriptedBackend final : public Backend {
 public:
  ScriptedBackend(std::int64_t fail_build, std::int64_t fail_update, std::int64_t fail_query,
                  double distance, std::optional<FirstContactResult> first_contact)
      : build_("build", fail_build),
        update_("update", fail_update),
        query_("query", fail_query),
        distance_(distance),
        first_contact_(first_contact) {}

  Capabilities capabilities() const override {
    Capabilities caps;
    caps.shape_kinds = static_cast<std::uint32_t>(ShapeKind::kTriangleMesh);
    caps.queries = QueryKindSet(QueryKind::kBoolean) | QueryKind::kAllPairs | QueryKind::kContacts |
                   QueryKind::kDistance;
    if (first_contact_) caps.queries |= QueryKind::kFirstContact;
    caps.update = true;
    caps.notes = "test backend: fails where scripted";
    return caps;
  }

  Result<std::unique_ptr<BackendModel>> build(const MeshView& /*mesh*/, const BuildNeeds& /*needs*/,
                                              const StateSibling& /*sibling*/) override {
    if (Status s = build_.next(); !s.ok()) return s;
    return std::unique_ptr<BackendModel>(std::make_unique<ScriptedModel>());
  }

  Status update(BackendModel& /*model*/, const Eigen::Ref<const Eigen::Matrix3Xd>& /*positions*/,
                UpdateCounters& /*counters*/) override {
    return update_.next();
  }

  Status query(BackendModel& /*a*/, const Pose& /*pose_a*/, BackendModel& /*b*/,
               const Pose& /*pose_b*/, const QueryRequest& request, QueryResult& result) override {
    if (request.kind == QueryKind::kDistance) {
      result.distance.distance = distance_;
      result.distance.point_a = Eigen::Vector3d::Zero();
      result.distance.point_b = Eigen::Vector3d::Zero();
    }
    if (request.kind == QueryKind::kFirstContact) result.first_contact = *first_contact_;
    return query_.next();
  }

 private:
  ScriptedCall build_;
  ScriptedCall update_;
  ScriptedCall query_;
  double distance_;
  std::optional<FirstContactResult> first_contact_;
};

Result<std::unique_ptr<Backend>> create(const std::string& /*variant*/, BackendOptions& options) {
  std::int64_t fail[3] = {0, 0, 0};
  const char* keys[3] = {"fail_build", "fail_update", "fail_query"};
  for (int k = 0; k < 3; ++k) {
    const Result<std::int64_t> value = options.getInt(keys[k], 0, 0, 1 << 30);
    if (!value.ok()) return value.status();
    fail[k] = value.value();
  }
  const Result<double> distance = options.getDouble("distance", 0.0, 0.0, 1e9);
  if (!distance.ok()) return distance.status();
  // First contact, offered only when scripted: apart, or a touch with touch_lo and touch_hi.
  std::optional<FirstContactResult> first_contact;
  const Result<bool> offers = options.getBool("first_contact", false);
  const Result<double> touch_lo = options.getDouble("touch_lo", -1.0, -1.0, 1.0);
  const Result<double> touch_hi = options.getDouble("touch_hi", -1.0, -1.0, 1.0);
  for (const Status& s :
       {offers.ok() ? Status() : offers.status(), touch_lo.ok() ? Status() : touch_lo.status(),
        touch_hi.ok() ? Status() : touch_hi.status()}) {
    if (!s.ok()) return s;
  }
  if (offers.value()) {
    first_contact.emplace();
    if (touch_hi.value() >= 0.0) {
      first_contact->touches = true;
      first_contact->t_lo = touch_lo.value();
      first_contact->t_hi = touch_hi.value();
    }
  }
  return std::unique_ptr<Backend>(std::make_unique<ScriptedBackend>(
      fail[0], fail[1], fail[2], distance.value(), first_contact));
}

const PluginInfo& describe() {
  static const PluginInfo info{
      "scripted",
      "1.0.0",
      "none (test backend)",
      "1.0.0",
      {{"scripted",
        "answers apart; fail_build/update/query=N fail; distance=D; "
        "first_contact=true answers first contacts apart, or touching with touch_lo=T;touch_hi=T"}},
      &create};
  return info;
}

}  // namespace
}  // namespace collido::test

COLLIDO_DEFINE_PLUGIN(scripted, collido::test::describe)

namespace collido::test {

std::shared_ptr<PluginLibrary> scriptedBackend() {
  Result<std::shared_ptr<PluginLibrary>> library =
      PluginLibrary::fromTable(collido_plugin_table_scripted(), "scripted (linked in)");
  EXPECT_TRUE(library.ok()) << library.status().toString();
  return library.ok() ? library.value() : nullptr;
}

}  // namespace collido::test
