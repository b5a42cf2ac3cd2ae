#include <collido/study/figures.h>

#include <cstdint>

#include <collido/runner/checks.h>
#include <collido/runner/measurement_json.h>
#include <collido/runner/time_statistic.h>

namespace collido::study {
namespace {

using Json = nlohmann::json;

template <typename T>
Json nullable(const std::optional<T>& value) {
  return value ? Json(*value) : Json();
}

// Frames for a per-frame figure (at least 1, so a measurement without frames shows 0).
double frameCount(const QueryMeasurement& m) {
  return m.frames.empty() ? 1.0 : static_cast<double>(m.frames.size());
}

Json perTriangle(std::optional<std::size_t> bytes, const QueryMeasurement& m) {
  if (!bytes || m.triangles == 0) return Json();
  return static_cast<double>(*bytes) / static_cast<double>(m.triangles);
}

// A work counter per query, where the backend counts it.
Json perQuery(bool counted, std::uint64_t FrameRecord::*counter, const QueryMeasurement& m) {
  if (!counted) return Json();
  std::uint64_t total = 0;
  for (const FrameRecord& f : m.frames)
    total += f.*counter;
  return static_cast<double>(total) / frameCount(m);
}

// A contact score's figure, where the query asked for contacts.
template <typename Figure>
Json contactFigure(const QueryMeasurement& m, const Figure& figure) {
  return m.contact ? Json(figure(*m.contact)) : Json();
}

Json mib(std::size_t bytes) {
  return static_cast<double>(bytes) / 1048576.0;
}

constexpr unsigned kBoth = kInSummary | kInDashboard;

// The registered checks' own figures (runner/checks.h) after the runner's.
std::vector<Figure> withCheckFigures(std::vector<Figure> figures) {
  for (const CheckFigure& check : checkFigures()) {
    figures.push_back({check.name, kBoth,
                       [value = check.value](const CombinationResult&, const QueryMeasurement& m) {
                         return nullable(value(m));
                       }});
  }
  return figures;
}

}  // namespace

const std::vector<Figure>& measurementFigures() {
  using R = const CombinationResult&;
  using M = const QueryMeasurement&;
  static const std::vector<Figure> figures = withCheckFigures({
      // The statistic every time figure shows (meanFrameTimeUs), with its interval; the call
      // percentiles after it describe single calls.
      {"time_us", kInDashboard, [](R, M m) { return Json(meanFrameTimeUs(m)); }},
      {"ci95_us", kBoth,
       [](R, M m) {
         const Interval ci = TimeBootstrap(m).ci95();
         return Json::array({ci.lo, ci.hi});
       }},
      // The timing rounds the calls came from, and how far their figures lay apart.
      {"rounds", kBoth, [](R, M m) { return Json(m.rounds); }},
      {"round_spread", kBoth, [](R, M m) { return nullable(roundSpread(m)); }},
      {"unstable", kBoth, [](R, M m) { return Json(unstable(m)); }},
      // The secondary figure: the repeated protocol's, measured beside the cycled one.
      {"repeated_protocol_us", kBoth, [](R, M m) { return nullable(m.repeated_us); }},
      {"median_us", kInDashboard, [](R, M m) { return Json(m.median_us); }},
      {"p90_us", kBoth, [](R, M m) { return Json(m.p90_us); }},
      {"p99_us", kBoth, [](R, M m) { return Json(m.p99_us); }},
      {"max_us", kBoth, [](R, M m) { return Json(m.max_us); }},
      {"frames", kBoth, [](R, M m) { return Json(m.frames.size()); }},
      {"disagreements", kBoth, [](R, M m) { return Json(m.disagreements); }},
      {"error_rate", kInDashboard,
       [](R, M m) { return Json(static_cast<double>(m.disagreements) / frameCount(m)); }},
      {"false_negatives", kBoth, [](R, M m) { return Json(m.false_negatives); }},
      {"false_positives", kBoth, [](R, M m) { return Json(m.false_positives); }},
      {"recall", kBoth, [](R, M m) { return Json(m.recall); }},
      {"precision", kBoth, [](R, M m) { return Json(m.precision); }},
      {"max_distance_error", kBoth, [](R, M m) { return nullable(m.max_distance_error); }},
      {"max_relative_distance_error", kBoth,
       [](R, M m) { return nullable(m.max_relative_distance_error); }},
      {"max_first_contact_error", kBoth, [](R, M m) { return nullable(m.max_first_contact_error); }},
      {"coarse_steps", kInDashboard,
       [](R, M m) {
         if (!queryKindInfo(m.kind).over_a_step) return Json();
         std::size_t coarse = 0;
         for (const FrameRecord& f : m.frames)
           coarse += f.coarserThanAsked() ? 1 : 0;
         return Json(coarse);
       }},
      {"contact", kInSummary,
       [](R, M m) { return m.contact ? contactScoreJson<Json>(*m.contact) : Json(); }},
      {"contacts_per_frame", kInDashboard,
       [](R, M m) {
         return contactFigure(m, [&m](const ContactScore& c) {
           return static_cast<double>(c.contacts) / frameCount(m);
         });
       }},
      {"contact_position_error", kInDashboard,
       [](R, M m) { return m.contact ? nullable(m.contact->position_error) : Json(); }},
      {"contact_surface_error", kInDashboard,
       [](R, M m) { return m.contact ? nullable(m.contact->surface_error) : Json(); }},
      {"contact_normal_error_deg", kInDashboard,
       [](R, M m) { return m.contact ? nullable(m.contact->normal_error_deg) : Json(); }},
      {"contact_depth_error", kInDashboard,
       [](R, M m) { return m.contact ? nullable(m.contact->depth_error) : Json(); }},
      {"contact_coverage", kInDashboard,
       [](R, M m) { return m.contact ? nullable(m.contact->coverage) : Json(); }},
      {"contact_false_pairs", kInDashboard,
       [](R, M m) {
         return contactFigure(m, [](const ContactScore& c) { return c.false_pairs; });
       }},
      {"finest_disagreements", kInSummary, [](R, M m) { return nullable(m.finest_disagreements); }},
      {"finest_error_rate", kInDashboard,
       [](R, M m) {
         return m.finest_disagreements
                    ? Json(static_cast<double>(*m.finest_disagreements) / frameCount(m))
                    : Json();
       }},
      {"floor_ratio", kBoth, [](R, M m) { return nullable(m.floor_ratio); }},
      {"reused_pairs", kBoth, [](R, M m) { return Json(m.reused_pairs); }},
      {"unasked_frames", kBoth, [](R, M m) { return Json(m.unasked_frames); }},
      {"skipped_pairs", kBoth, [](R, M m) { return Json(m.skipped_pairs); }},
      {"update_median_us", kBoth, [](R, M m) { return nullable(m.update_median_us); }},
      {"build_ms", kBoth, [](R, M m) { return Json(m.build_ms); }},
      {"triangles", kBoth, [](R, M m) { return Json(m.triangles); }},
      {"bytes_per_triangle", kBoth,
       [](R, M m) {
         return Json(m.triangles == 0
                         ? 0.0
                         : static_cast<double>(m.memory_bytes) / static_cast<double>(m.triangles));
       }},
      {"heap_bytes_per_triangle", kBoth, [](R, M m) { return perTriangle(m.heap_bytes, m); }},
      {"heap_peak_bytes_per_triangle", kInDashboard,
       [](R, M m) { return perTriangle(m.heap_peak_bytes, m); }},
      {"peak_rss_bytes", kInSummary, [](R r, M) { return Json(r.outcome.peak_rss_bytes); }},
      {"backend_rss_bytes", kInSummary, [](R r, M) { return Json(r.residentBytes()); }},
      {"peak_rss_mib", kInDashboard, [](R r, M) { return mib(r.outcome.peak_rss_bytes); }},
      {"backend_rss_mib", kInDashboard, [](R r, M) { return mib(r.residentBytes()); }},
      {"bv_tests", kBoth,
       [](R, M m) { return perQuery(m.counts_bv_tests, &FrameRecord::bv_tests, m); }},
      {"primitive_tests", kBoth,
       [](R, M m) { return perQuery(m.counts_primitive_tests, &FrameRecord::primitive_tests, m); }},
  });
  return figures;
}

}  // namespace collido::study
