#pragma once
// Observers of the runner's frame stepping (backend_run.cpp). Each adds one kind of figure to a
// frame's record, from the object pairs asked and the frame's shapes: a new check is a new
// observer, not another branch in the stepping loop.
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <collido/runner/floor.h>
#include <collido/runner/runner.h>
#include <collido/scene/broad_phase.h>

namespace collido::detail {

using ObjectPairs = std::vector<std::pair<std::size_t, std::size_t>>;

/// The object pairs a query asks in `frame`: its pair, or those of a group the shared broad
/// phase keeps. The run and the oracle's precomputation must ask the same ones.
ObjectPairs objectPairsAt(const std::optional<BroadPhase>& broad_phase, const SceneQuery& query,
                          std::size_t frame);

/// One object pair of a frame, after its checked (untimed) call.
struct AskedPair {
  std::size_t frame = 0;
  std::size_t a = 0;
  std::size_t b = 0;
  const TriangleMesh& shape_a;
  const TriangleMesh& shape_b;
  const Pose& pose_a;
  const Pose& pose_b;
  const QueryRequest& request;
  const QueryResult& reported;
  const OracleAnswer& truth;
};

/// A frame whose object pairs were all asked, and timed by the repeated protocol.
struct SteppedFrame {
  std::size_t frame = 0;
  const ObjectPairs& candidates;
  const std::map<std::size_t, std::shared_ptr<const TriangleMesh>>& shapes;
};

/// Adds figures to a frame's record while the runner steps through a query's frames.
class FrameObserver {
 public:
  virtual ~FrameObserver() = default;
  /// After each object pair's checked call.
  virtual void pair(const AskedPair& asked, FrameRecord& record);
  /// After the frame's timed calls (not called for a frame that failed).
  virtual void frame(const SteppedFrame& stepped, FrameRecord& record);
};

/// The answer against the oracle's (compareWithOracle), summed over the frame's pairs.
class OracleComparison final : public FrameObserver {
 public:
  void pair(const AskedPair& asked, FrameRecord& record) override;
};

/// Every pair's answers, the backend's and the oracle's (RunOptions::keep_answers, what
/// `collido view` shows).
class AnswerKeeper final : public FrameObserver {
 public:
  void pair(const AskedPair& asked, FrameRecord& record) override;
};

/// All-pairs queries: the floor, one exact triangle test per truly intersecting pair on the
/// world coordinates, timed after the frame's timed calls (runner/floor.h).
class FloorTimer final : public FrameObserver {
 public:
  explicit FloorTimer(int repetitions) : repetitions_(repetitions) {}
  void pair(const AskedPair& asked, FrameRecord& record) override;
  void frame(const SteppedFrame& stepped, FrameRecord& record) override;

 private:
  int repetitions_;
  std::vector<WorldTrianglePair> true_pairs_;
};

/// A coarser mesh's answer against the finest meshes' (FrameRecord::finest_intersecting).
class FinestComparison final : public FrameObserver {
 public:
  FinestComparison(OracleCache& finest, const SceneQuery& query);
  void frame(const SteppedFrame& stepped, FrameRecord& record) override;

 private:
  OracleCache& finest_;
  const SceneQuery& query_;
  std::optional<BroadPhase> broad_phase_;
};

/// Objects posed from tracked markers: whether the objects intersect at their true poses, and
/// the "possible contact within tracking error" answer (FrameRecord::truth_intersecting,
/// possible_contact). `truth` holds the scene at its true poses.
class TrackingComparison final : public FrameObserver {
 public:
  TrackingComparison(const Scene& scene, OracleCache& truth, const SceneQuery& query,
                     double sigmas);
  void frame(const SteppedFrame& stepped, FrameRecord& record) override;

 private:
  const Scene& scene_;
  OracleCache& truth_;
  const SceneQuery& query_;
  double sigmas_;
  std::optional<BroadPhase> broad_phase_;
};

}  // namespace collido::detail
