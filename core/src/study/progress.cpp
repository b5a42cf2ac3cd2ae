#include <collido/study/progress.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace collido::study {

std::string formatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long total = std::lround(seconds);
  char text[32];
  if (total < 60) {
    std::snprintf(text, sizeof text, "%lds", total);
  } else if (total < 3600) {
    std::snprintf(text, sizeof text, "%ldm%02lds", total / 60, total % 60);
  } else {
    std::snprintf(text, sizeof text, "%ldh%02ldm", total / 3600, (total % 3600) / 60);
  }
  return text;
}

std::string progressBar(double fraction, std::size_t width) {
  fraction = std::clamp(std::isfinite(fraction) ? fraction : 0.0, 0.0, 1.0);
  const auto filled = static_cast<std::size_t>(std::lround(fraction * static_cast<double>(width)));
  std::string bar;
  for (std::size_t i = 0; i < width; ++i)
    bar += i < filled ? "\u2588" : "\u2591";
  return bar;
}

StudyProgress::StudyProgress(std::ostream& out, std::size_t combinations, bool interactive, Now now)
    : out_(out),
      combinations_(combinations),
      interactive_(interactive),
      now_(std::move(now)),
      started_(now_()) {}

void StudyProgress::start(std::size_t index, const std::string& label) {
  index_ = index;
  label_ = label;
  frames_done_ = 0;
  frames_total_ = 0;
  draw();
}

void StudyProgress::frames(std::size_t done, std::size_t total) {
  frames_done_ = done;
  frames_total_ = total;
}

void StudyProgress::setExpected(std::vector<double> seconds) {
  expected_ = std::move(seconds);
}

std::string StudyProgress::estimateLeft() const {
  const double elapsed = std::chrono::duration<double>(now_() - started_).count();
  const double current =
      frames_total_ == 0 ? 0.0 : static_cast<double>(frames_done_) / frames_total_;
  if (expected_.size() == combinations_) {
    double expected_done = 0.0;
    double expected_left = 0.0;
    for (std::size_t i = 0; i < expected_.size(); ++i) {
      const double part = i < finished_ ? 1.0 : i == finished_ ? current : 0.0;
      expected_done += expected_[i] * part;
      expected_left += expected_[i] * (1.0 - part);
    }
    if (expected_done + expected_left > 0.0) {
      // Before anything has run, or on a machine like the one that measured: as expected.
      const double pace = expected_done > 0.0 ? elapsed / expected_done : 1.0;
      return formatDuration(expected_left * pace);
    }
  }
  const double done = static_cast<double>(finished_) + current;
  if (done <= 0.0) return "?";
  return formatDuration(elapsed / done * (static_cast<double>(combinations_) - done));
}

void StudyProgress::finish(const std::string& outcome) {
  ++finished_;
  // The finished combination now counts whole; its frames must not count a second time.
  frames_done_ = 0;
  frames_total_ = 0;
  if (interactive_) {
    out_ << "\r\x1b[K";
  }
  out_ << "[" << index_ + 1 << "/" << combinations_ << "] " << label_ << ": " << outcome
       << "  (left: " << estimateLeft() << ")\n";
  out_.flush();
}

void StudyProgress::tick() {
  if (!interactive_) return;
  if (now_() - last_draw_ < std::chrono::milliseconds(100)) return;
  draw();
}

void StudyProgress::draw() {
  if (!interactive_) return;
  last_draw_ = now_();
  const double current =
      frames_total_ == 0 ? 0.0 : static_cast<double>(frames_done_) / frames_total_;
  const double overall =
      combinations_ == 0 ? 1.0 : (static_cast<double>(finished_) + current) / combinations_;
  char percent[16];
  std::snprintf(percent, sizeof percent, "%3.0f%%", overall * 100.0);
  std::string label = label_;
  if (label.size() > 48) label = label.substr(0, 45) + "...";
  out_ << "\r\x1b[K" << progressBar(overall, 24) << " " << percent << " " << finished_ << "/"
       << combinations_ << " left " << estimateLeft() << " | " << label << " "
       << progressBar(current, 10) << " " << frames_done_ << "/" << frames_total_;
  out_.flush();
}

}  // namespace collido::study
