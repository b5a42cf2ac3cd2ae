#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <collido/host/plugin_library.h>
#include <collido/oracle/exact_oracle.h>
#include <collido/query.h>
#include <collido/runner/contact_score.h>
#include <collido/runner/measurement_status.h>
#include <collido/scene/scene.h>

namespace collido {

/// A backend to run: a variant of a loaded plugin, with options ("obbtree[max_leaf_triangles=4]").
struct BackendSpec {
  std::shared_ptr<PluginLibrary> library;
  std::string variant;
  std::map<std::string, std::string> options;

  /// "variant" or "variant[key=value;...]", as shown in tables.
  std::string label() const;
  /// The runner's own option "substeps=N" (1 to 4096; resolveBackends checks it), 0 without:
  /// a query over a step is answered by the runner from the backend's boolean answers at the
  /// N + 1 evenly spaced times of the step, t = k / N (a planner's discrete checks at a
  /// resolution); the first that touches, at k, gives the bracket [(k - 1) / N, k / N], none
  /// gives no contact. Every other query is the backend's own answer.
  int substeps() const;
  /// `options` without the runner's own: what the plugin is given.
  std::map<std::string, std::string> pluginOptions() const;
};

/// The runner's backend option key (BackendSpec::substeps).
inline constexpr const char* kSubstepsOption = "substeps";

/// Parses "variant" or "variant[key=value;key=value]" into a variant and options.
Result<std::pair<std::string, std::map<std::string, std::string>>> parseBackendText(
    const std::string& text);

/// The error for a backend variant no plugin offers, listing the `known` ones.
Status unknownBackend(const std::string& variant, const std::vector<std::string>& known);

/// Picks, for each text, the plugin offering that variant. Errors name the unknown variant and
/// list the known ones.
Result<std::vector<BackendSpec>> resolveBackends(
    const std::vector<std::string>& texts,
    const std::vector<std::shared_ptr<PluginLibrary>>& plugins);

/// How a run measures.
/// How the timed calls of a query are ordered (docs/STUDY.md, "Timing protocols").
enum class TimingProtocol {
  /// Per frame: one untimed call (the answer checked), then `repetitions` timed calls on that
  /// same frame. Its data stays in cache: the best case.
  kRepeated,
  /// One untimed pass over every frame (answers checked), then `repetitions` passes that time one
  /// call per frame, each on another frame than the last, as a physics step meets them;
  /// deforming objects are updated to each frame, untimed, before its call.
  kCycled,
};

/// "repeated" or "cycled".
const char* timingProtocolName(TimingProtocol protocol);
/// The protocol of that name, or nullopt.
std::optional<TimingProtocol> parseTimingProtocol(const std::string& name);

struct RunOptions {
  int repetitions = 5;  ///< timed calls per frame and query (see `protocol`)
  TimingProtocol protocol = TimingProtocol::kRepeated;
  /// Under the cycled protocol: after its passes, time each frame this many more calls back to
  /// back, after one untimed call on it, for the repeated protocol's figure beside the cycled one
  /// (QueryMeasurement::repeated_us); 0 measures none.
  int repeated_calls = 0;
  /// Build every object for every query kind the backend answers, not only the ones the scene
  /// asks of it: shows what building only the needed structures saves.
  bool build_every_need = false;
  std::function<void(const std::string&)> progress;  ///< called with a line per step; may be empty
  /// Called after each frame of each query with (frames done, frames in all); may be empty.
  std::function<void(std::size_t, std::size_t)> frame_progress;
  /// Objects posed from tracked markers: the margin of the "possible contact" answer is this
  /// many times the sum of the objects' predicted spreads (TrackedFrame::sigma) in the frame.
  double tracking_sigmas = 3.0;
  /// Keep every frame's answers, the backend's and the oracle's, per object pair asked
  /// (FrameRecord::answers): what `collido view` shows triangle by triangle.
  bool keep_answers = false;
  /// Answer an object pair with its answer of the frame before when neither object moved,
  /// changed state or deformed since then (FrameRecord::reused_pairs), as an application that
  /// knows what it moved would; the reused answer is still checked against the oracle. Off,
  /// every pair is asked in every frame: the cold figure.
  bool reuse_unchanged = false;
  /// Put two-object queries other than distance through the shared broad phase too: a pair
  /// whose world boxes are apart in a frame is not asked (its answer is "apart", which the
  /// oracle check still holds it to) and counts in FrameRecord::skipped_pairs. Group queries
  /// always go through it. Off, every two-object pair is asked in every frame.
  bool skip_apart_pairs = false;
};

/// One object pair's answers in a frame, kept with RunOptions::keep_answers.
struct PairAnswers {
  std::size_t a = 0;  ///< object index (Scene::objects)
  std::size_t b = 0;
  QueryResult reported;  ///< the backend's answer (timing counters included)
  bool oracle_intersecting = false;
  std::vector<TrianglePair> oracle_pairs;  ///< all pairs, or one witness (boolean queries)
  std::optional<DistanceResult> oracle_distance;
};

/// The comparison of one frame's answer with the oracle's.
struct FrameRecord {
  std::size_t frame = 0;
  bool oracle_intersecting = false;
  bool reported_intersecting = false;
  std::size_t oracle_pairs = 0;    ///< kAllPairs: size of the exact set
  std::size_t reported_pairs = 0;  ///< distinct pairs the backend reported
  std::size_t matched_pairs = 0;   ///< reported pairs in the exact set
  std::size_t invalid_pairs = 0;   ///< out-of-range or duplicate pairs, and false witnesses
  bool truncated = false;
  double median_us = 0.0;  ///< median of this frame's timed calls
  /// kAllPairs: the floor, the median time of one exact triangle test per pair the oracle finds
  /// (runner/floor.h), measured beside the timed calls.
  std::optional<double> floor_us;
  /// With deforming objects: the time of this frame's update() calls (movable nodes), one call
  /// per deforming object, timed once (a repeated update with the same positions could be
  /// cheaper than a real one). Switching active states selects a model and costs nothing.
  std::optional<double> update_us;
  /// The work those update() calls reported, summed (counted false when the backend does not
  /// count it: Capabilities::counts_update_work).
  UpdateCounters update_work;
  /// With a finest scene: whether the objects, meshed at the finest resolution, intersect.
  std::optional<bool> finest_intersecting;
  /// With objects posed from tracked markers: whether the objects intersect at their true
  /// poses (the oracle's answers above are on the recovered poses every backend is given).
  std::optional<bool> truth_intersecting;
  /// With objects posed from tracked markers, where their uncertainty is known: whether the
  /// objects come within `tracking_margin` at the recovered poses — a possible contact within
  /// tracking error, beside the exact answer (RunOptions::tracking_sigmas).
  std::optional<bool> possible_contact;
  std::optional<double> tracking_margin;
  /// kDistance: the exact distance (exactMeshDistance) and the reported one.
  std::optional<double> oracle_distance;
  std::optional<double> reported_distance;
  /// kDistance: how far below the exact distance the answer may lie (rounding: 1e-10 of the
  /// largest posed coordinate) and how far above it (that, plus the request's tolerance).
  double distance_below = 0.0;
  double distance_above = 0.0;
  /// kDistance: the reported points are not the reported distance apart, or not on their
  /// reported triangles, or a certified interval misses the exact distance (all within
  /// `distance_below`).
  bool invalid_distance_witness = false;
  /// kContacts: the contacts held to the exact reference (docs/DESIGN.md, "Contact geometry").
  std::optional<ContactScore> contact;
  /// kFirstContact: whether the shapes touch over the step (unset where the oracle could not
  /// decide: a grazing pass within rounding), the oracle's bracket and the reported one (where
  /// the backend says they touch), and the largest error of a first-contact time within the
  /// reported bracket, max(reported t_hi - oracle t_lo, oracle t_hi - reported t_lo), where both
  /// say they touch. oracle_intersecting and reported_intersecting hold the verdicts (the
  /// backend's verdict stands for the oracle's where the oracle could not decide).
  std::optional<bool> oracle_touches;
  std::optional<double> oracle_t_lo;
  std::optional<double> oracle_t_hi;
  std::optional<double> reported_t_lo;
  std::optional<double> reported_t_hi;
  std::optional<double> first_contact_error;
  /// kFirstContact: the bracket width the query asked for.
  std::optional<double> bracket_width;
  /// kFirstContact: the reported bracket contradicts the oracle's by more than the bracket width
  /// asked for (its contact lies that far inside the oracle's proven free part, or its free part
  /// reaches that far past the oracle's proven contact), or its witness pair does not share a
  /// point at its t_hi (decided exactly).
  bool invalid_first_contact = false;
  std::uint64_t bv_tests = 0;
  std::uint64_t primitive_tests = 0;
  /// Object pairs asked: 1 for a two-object query (0 where RunOptions::skip_apart_pairs culled
  /// it); for a group query, the candidates the shared broad phase passed (every count above is
  /// summed over them).
  std::size_t object_pairs = 1;
  /// With RunOptions::reuse_unchanged: of those, the pairs answered with their answer of the
  /// frame before, not asked (neither object moved, changed state or deformed). Their time is
  /// not in this frame's timed calls, and an unchanged deforming object is not updated.
  std::size_t reused_pairs = 0;
  /// Object pairs the query asks about that the shared broad phase proved apart in this frame,
  /// so were not asked (group queries; two-object ones with RunOptions::skip_apart_pairs).
  std::size_t skipped_pairs = 0;
  /// With RunOptions::keep_answers: the answers of every object pair asked, in order.
  std::vector<PairAnswers> answers;
  /// The registered checks' per-frame values (runner/checks.h), by their declared names; a
  /// check that did not measure this frame leaves its names out.
  std::map<std::string, double> values;

  /// Whether the answer differs from the oracle's in any way this query asks about; for a first
  /// contact that includes a time coarser than asked (coarserThanAsked).
  bool disagrees(QueryKind kind) const;
  /// kFirstContact: the time error is above twice the bracket width asked (two brackets of that
  /// width around the true time are at most that far apart): a coarser answer than the query
  /// asks for, as discrete sub-steps give.
  bool coarserThanAsked() const;
};

/// Compares a backend's answer with the oracle's for meshes posed by `pose_a` and `pose_b` and
/// fills the answer fields of `record`: out-of-range and repeated pairs and (for boolean
/// queries) witnesses that do not intersect count as invalid; all-pairs answers are matched
/// against the exact set; distances against the exact distance (truth.distance), within the
/// request's tolerance and rounding, their points checked against their triangles.
void compareWithOracle(const TriangleMesh& a, const Pose& pose_a, const TriangleMesh& b,
                       const Pose& pose_b, const QueryRequest& request, const QueryResult& result,
                       const OracleAnswer& truth, FrameRecord& record);

/// Results of one (backend, scene, query).
struct QueryMeasurement {
  std::string backend;
  std::string scene;
  std::string query;
  QueryKind kind = QueryKind::kBoolean;
  MeasurementStatus status;  ///< ok, skipped (by design) or failed, with the reason
  std::vector<FrameRecord> frames;
  /// Every timed call, frame by frame (each frame's calls together); with several rounds, each
  /// frame's calls round after round, the same number from each.
  std::vector<double> times_us;
  /// The worker processes (a study's timing rounds) the timed calls came from.
  std::size_t rounds = 1;
  TimingProtocol protocol = TimingProtocol::kRepeated;  ///< how they were ordered
  /// With RunOptions::repeated_calls: the secondary figure, the repeated protocol's, measured in
  /// the same process after the cycled calls: the mean over frames of each frame's median
  /// back-to-back call.
  std::optional<double> repeated_us;
  double median_us = 0.0;
  double p90_us = 0.0;
  double p99_us = 0.0;
  double max_us = 0.0;
  std::size_t false_negatives = 0;  ///< frames reported disjoint that intersect
  std::size_t false_positives = 0;  ///< frames reported intersecting that are disjoint
  std::size_t disagreements = 0;    ///< frames whose answer differs from the oracle's
  /// With a finest scene: frames whose boolean answer differs from the finest meshes' truth,
  /// the error of answering on a coarser mesh.
  std::optional<std::size_t> finest_disagreements;
  /// With objects posed from tracked markers: frames where the exact answer on the recovered
  /// poses says contact and the true poses do not (false contacts), and the reverse (missed):
  /// the collision error tracking error causes, whatever the backend.
  std::optional<std::size_t> tracking_false_contacts;
  std::optional<std::size_t> tracking_missed_contacts;
  /// Frames with a possible contact within tracking error, and true-pose contacts that even
  /// that answer missed (the margin was too small for the real error).
  std::optional<std::size_t> tracking_possible_contacts;
  std::optional<std::size_t> tracking_missed_within_margin;
  /// kDistance: the largest |reported - exact| distance over the frames, absolute and relative
  /// to the exact distance (frames at distance 0 count in the absolute figure only).
  std::optional<double> max_distance_error;
  std::optional<double> max_relative_distance_error;
  /// kFirstContact: the largest FrameRecord::first_contact_error over the frames.
  std::optional<double> max_first_contact_error;
  /// kContacts: the frames' contact scores folded together (maxima of the errors, coverage of
  /// all frames' intersection curves together); unset for other queries.
  std::optional<ContactScore> contact;
  double recall = 1.0;     ///< kAllPairs: matched / exact pairs over all frames (1 if none)
  double precision = 1.0;  ///< kAllPairs: matched / reported pairs over all frames (1 if none)
  bool counts_bv_tests = false;
  bool counts_primitive_tests = false;
  /// kAllPairs: the frames' median times summed over their floors summed (frames with a floor
  /// whose every pair was asked); 1 would be an answer that costs one exact triangle test per
  /// true pair and nothing else.
  std::optional<double> floor_ratio;
  /// With RunOptions::reuse_unchanged: FrameRecord::reused_pairs summed over the frames, and the
  /// frames answered without asking the backend anything (every pair reused, or culled by the
  /// shared broad phase).
  std::size_t reused_pairs = 0;
  std::size_t unasked_frames = 0;
  /// FrameRecord::skipped_pairs summed over the frames.
  std::size_t skipped_pairs = 0;
  /// With deforming objects: the median over frames of FrameRecord::update_us.
  std::optional<double> update_median_us;
  /// With deforming objects, where the backend counts: structures it rebuilt over all frames.
  std::optional<std::uint64_t> update_rebuilds;
  double build_ms = 0.0;                          ///< objects queried (every state's model)
  std::size_t triangles = 0;                      ///< objects queried
  std::size_t memory_bytes = 0;                   ///< objects queried, as the backend reports
  std::optional<std::size_t> heap_bytes;          ///< objects queried, measured around build
  std::optional<std::size_t> heap_peak_bytes;     ///< objects queried, most live in build (hooks)
  std::optional<std::uint64_t> heap_allocations;  ///< objects queried, calls in build (hooks)
  std::string heap_probe;                         ///< which probe measured: heapProbeName()

  bool ok() const { return status.ok(); }
};

/// Everything a run measured.
struct RunReport {
  std::vector<QueryMeasurement> measurements;
  std::vector<std::string> problems;  ///< backends that could not be created, etc.
};

/// Exact oracle answers of one scene, computed on first use and kept, keyed by (object a,
/// object b, frame). One cache serves every backend run on the scene, so the oracle runs once;
/// a study also keeps it on disk between its worker processes (study/oracle_store.h). The scene
/// must outlive it.
class OracleCache {
 public:
  using Key = std::tuple<std::size_t, std::size_t, std::size_t>;  ///< object a, object b, frame

  /// `witness_only`: every answer needs only whether the objects intersect.
  explicit OracleCache(const Scene& scene, bool witness_only = false)
      : scene_(scene), witness_only_(witness_only) {}

  /// The answer for objects `a` and `b` in `frame`: all pairs when some all-pairs query of the
  /// scene asks about both, else a witness; with `distance`, the exact distance too (computed on
  /// the first distance query that asks, so backends that answer no distance never pay for it).
  const OracleAnswer& get(std::size_t a, std::size_t b, std::size_t frame, bool distance = false);
  /// get()'s answer with the first contact over the step from `frame` to the next, bracketed to
  /// `width` at most (computed on first use, and again when a narrower bracket is asked).
  const OracleAnswer& getStep(std::size_t a, std::size_t b, std::size_t frame, double width);
  /// The answer `query` is checked against for objects `a` and `b` in `frame`: what its kind's
  /// QueryKindInfo::oracle says (with `distances` false, a distance query's needs no distance).
  const OracleAnswer& answerFor(const SceneQuery& query, std::size_t a, std::size_t b,
                                std::size_t frame, bool distances = true);
  const Scene& scene() const { return scene_; }
  bool witnessOnly() const { return witness_only_; }

  /// Every answer computed or added so far.
  const std::map<Key, OracleAnswer>& answers() const { return answers_; }
  /// Adds an answer computed elsewhere for this same scene (see fingerprint()).
  void add(const Key& key, OracleAnswer answer) { answers_.emplace(key, std::move(answer)); }
  /// How many answers and distances this cache has computed itself: grows whenever there is
  /// something new to keep (a distance added to a known answer included).
  std::size_t computed() const { return computed_; }
  /// A digest (XXH3-128, 32 hex digits) of everything the answers depend on: each object's
  /// vertices, triangles and poses, the frames, the queries' kinds and objects, and
  /// witness_only. Two caches with equal fingerprints hold interchangeable answers.
  std::string fingerprint() const;
  /// The sizes of those inputs ("frames 24, queries 3, objects 1839v 3674t 1p / ..."): stored
  /// beside the answers and compared on a hit, a second check beside the digest.
  std::string inputSizes() const;

 private:
  const Scene& scene_;
  bool witness_only_;
  std::map<Key, OracleAnswer> answers_;
  std::size_t computed_ = 0;
};

/// Runs every query of every scene on every backend, checks each answer against the exact
/// oracle (computed once per scene, frame and query, shared by all backends) and times it.
/// Backends that cannot answer a query are recorded as skipped, failures as failed; nothing is
/// silently dropped.
/// Asks `oracle` every answer a run of its scene will (each query, frame and object pair the
/// shared broad phase gives, with distances for distance queries when `distances`), so that a
/// worker can compute them before the backend's memory is measured rather than during it.
void precomputeOracleAnswers(OracleCache& oracle, bool distances = true);

RunReport runScenes(const std::vector<Scene>& scenes, const std::vector<BackendSpec>& backends,
                    const RunOptions& options);

/// One scene of runScenes: every backend on `scene`, the answers checked against `oracle` (a
/// cache of this scene's, which the caller may have filled from a store), the measurements
/// appended to `report`.
void runSceneOnBackends(const Scene& scene, const std::vector<BackendSpec>& backends,
                        const RunOptions& options, OracleCache& oracle, RunReport& report);

/// Runs one scene on one backend. With `finest` (the same scene meshed at its finest
/// resolution, with the same poses), each frame also records whether the finest meshes
/// intersect, so the error of a coarse mesh is measured against the shape it stands for.
RunReport runScene(const Scene& scene, const BackendSpec& backend, const RunOptions& options,
                   const Scene* finest = nullptr);

/// As runScene, with the oracle's answers taken from (and added to) `oracle`, a cache of this
/// scene's (and `finest_oracle`, a witness-only cache of the finest scene's, when measuring a
/// coarse mesh's error): runs of several backends on one scene then compute each answer once.
RunReport runScene(const Scene& scene, const BackendSpec& backend, const RunOptions& options,
                   OracleCache& oracle, OracleCache* finest_oracle = nullptr);

/// Summary statistics of a measurement from its frames and timed calls.
void summariseMeasurement(QueryMeasurement& measurement);

/// The table people read: one row per (backend, scene, query).
std::string formatRunTable(const RunReport& report);

/// The report as JSON (nlohmann dump), with per-frame records.
std::string runReportJson(const RunReport& report);

}  // namespace collido
