#include <collido/runner/measurement_status.h>

namespace collido {

MeasurementStatus MeasurementStatus::fromText(const std::string& text) {
  if (text == "ok") return {};
  const std::string skipped_prefix = "skipped: ";
  const std::string failed_prefix = "failed: ";
  if (text.rfind(skipped_prefix, 0) == 0) return skipped(text.substr(skipped_prefix.size()));
  if (text.rfind(failed_prefix, 0) == 0) return failed(text.substr(failed_prefix.size()));
  return failed(text);
}

std::string MeasurementStatus::text() const {
  switch (state_) {
    case State::kOk:
      return "ok";
    case State::kSkipped:
      return "skipped: " + reason_;
    case State::kFailed:
      return "failed: " + reason_;
  }
  return "failed: " + reason_;
}

}  // namespace collido
