#pragma once

#include <ostream>
#include <string>

namespace collido {

/// How a measurement ended: measured, skipped by design (the backend does not answer that query,
/// build that shape or update models) or failed (a build, update or query the engine refused),
/// with the reason. Its text form ("ok", "skipped: why", "failed: why") is what JSON, tables and
/// the dashboard carry.
class MeasurementStatus {
 public:
  enum class State { kOk, kSkipped, kFailed };

  MeasurementStatus() = default;  ///< ok
  static MeasurementStatus skipped(std::string reason) {
    return MeasurementStatus(State::kSkipped, std::move(reason));
  }
  static MeasurementStatus failed(std::string reason) {
    return MeasurementStatus(State::kFailed, std::move(reason));
  }
  /// From the text form; anything but "ok" and "skipped: ..." counts as failed, with the text as
  /// its reason.
  static MeasurementStatus fromText(const std::string& text);

  State state() const { return state_; }
  const std::string& reason() const { return reason_; }
  bool ok() const { return state_ == State::kOk; }
  bool skipped() const { return state_ == State::kSkipped; }
  bool failed() const { return state_ == State::kFailed; }
  std::string text() const;

 private:
  MeasurementStatus(State state, std::string reason) : state_(state), reason_(std::move(reason)) {}

  State state_ = State::kOk;
  std::string reason_;
};

inline bool operator==(const MeasurementStatus& a, const MeasurementStatus& b) {
  return a.state() == b.state() && a.reason() == b.reason();
}
inline bool operator!=(const MeasurementStatus& a, const MeasurementStatus& b) {
  return !(a == b);
}
inline bool operator==(const MeasurementStatus& status, const std::string& text) {
  return status.text() == text;
}
inline bool operator==(const MeasurementStatus& status, const char* text) {
  return status.text() == text;
}
inline bool operator!=(const MeasurementStatus& status, const char* text) {
  return !(status == text);
}
inline std::ostream& operator<<(std::ostream& out, const MeasurementStatus& status) {
  return out << status.text();
}

}  // namespace collido
