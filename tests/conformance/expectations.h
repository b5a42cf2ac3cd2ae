#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>

#include <collido/runner/runner.h>
#include <collido/status.h>

namespace collido::conformance {

/// How one (scene, query) answered against the exact oracle, summed over its frames.
struct Disagreement {
  std::size_t disagreeing_frames = 0;
  std::size_t false_negatives = 0;  ///< frames reported disjoint that intersect
  std::size_t false_positives = 0;  ///< frames reported intersecting that are disjoint
  std::size_t missed_pairs = 0;     ///< exact pairs not reported (all_pairs)
  std::size_t extra_pairs = 0;      ///< reported pairs that do not intersect (all_pairs)
  std::size_t invalid_pairs = 0;    ///< out of range, duplicated, or false witnesses (a
                                    ///< boolean's pair, a distance's points)
  /// Contacts (docs/DESIGN.md, "Contact geometry"): naming a pair that does not meet, off their
  /// pair's exact set beyond rounding (or standing for no pair), and with a non-unit normal or
  /// a negative depth.
  std::size_t false_contact_pairs = 0;
  std::size_t contacts_off_set = 0;
  std::size_t malformed_contacts = 0;

  bool none() const;
  bool operator==(const Disagreement& o) const;
  std::string toString() const;
};

/// The counts of one compared frame of a query of kind `kind`.
Disagreement disagreementOf(const FrameRecord& frame, QueryKind kind);

/// The counts of a measured query: the sum over its frames.
Disagreement disagreementOf(const QueryMeasurement& m);

/// What a variant is expected to do, from tests/conformance/expectations/<variant>.json:
///   {"variant": "fcl:obb", "exact": false,
///    "measured": {"<scene>/<query>": {"disagreeing_frames": 0, ...}, ...}}
/// "exact": true means zero disagreements everywhere (a hard requirement); otherwise every
/// (scene, query) listed must match its counts exactly, and one not listed must be exact. A
/// variant without a file must be exact.
struct Expectations {
  std::string file;  ///< where it came from, for messages; empty when there is none
  bool exact = true;
  std::map<std::string, Disagreement> measured;

  /// The counts expected for "<scene>/<query>".
  Disagreement expectedFor(const std::string& key) const;
};

/// File name of a variant's expectations ("fcl:obb" -> "fcl_obb.json").
std::string expectationsFileName(const std::string& variant);

/// Reads `directory`/<variant>.json; no file gives the exact default.
Result<Expectations> loadExpectations(const std::string& directory, const std::string& variant);

/// Records measured counts for a variant (merging into an existing file in `directory`).
Status recordMeasurement(const std::string& directory, const std::string& variant,
                         const std::string& key, const Disagreement& counts);

}  // namespace collido::conformance
