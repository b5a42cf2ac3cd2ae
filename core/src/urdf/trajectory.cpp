#include "trajectory.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include <boost/tokenizer.hpp>

#include <collido/mesh/input_file.h>
#include <collido/random/portable_random.h>

namespace collido::urdf_import {
namespace {

using Cells = std::vector<std::string>;

// One CSV line's cells (quotes and escapes as Boost's escaped_list_separator reads them),
// trimmed of spaces.
Cells cellsOf(const std::string& line) {
  Cells cells;
  boost::tokenizer<boost::escaped_list_separator<char>> tokens(line);
  for (const std::string& cell : tokens) {
    const std::size_t first = cell.find_first_not_of(" \t\r");
    const std::size_t last = cell.find_last_not_of(" \t\r");
    cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
  }
  return cells;
}

}  // namespace

std::vector<double> referenceConfiguration(const RobotModel& robot) {
  // MoveIt's default state: 0, or the middle of the limits when they exclude 0.
  std::vector<double> values(robot.joints.size(), 0.0);
  for (std::size_t j = 0; j < robot.joints.size(); ++j) {
    const Joint& joint = robot.joints[j];
    if (joint.clamped(0.0) != 0.0) values[j] = 0.5 * (joint.lower + joint.upper);
  }
  return values;
}

Result<Trajectory> readTrajectory(const std::string& path, const RobotModel& robot) {
  Result<std::string> text = readInputFile(path, "joints CSV");
  if (!text.ok()) return text.status();
  const auto fail = [&path](const std::string& where, const std::string& problem) {
    return Status(StatusCode::kInvalidArgument, path + ": " + where + ": " + problem);
  };
  std::istringstream lines(text.value());
  std::string line;
  std::vector<std::size_t> columns;  // joint per column
  Trajectory frames;
  std::size_t number = 0;
  try {
    while (std::getline(lines, line)) {
      ++number;
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      const Cells cells = cellsOf(line);
      if (columns.empty()) {
        for (const std::string& name : cells) {
          const std::optional<std::size_t> joint = robot.jointNamed(name);
          const std::string where = "line " + std::to_string(number);
          if (!joint || !robot.joints[*joint].moves() || robot.joints[*joint].mimics) {
            return fail(where, "column '" + name + "' names no moving joint of robot '" +
                                   robot.name + "'" +
                                   (joint ? " (it is fixed, or mimics another)" : ""));
          }
          if (std::find(columns.begin(), columns.end(), *joint) != columns.end())
            return fail(where, "joint '" + name + "' has two columns");
          columns.push_back(*joint);
        }
        continue;
      }
      if (cells.size() != columns.size()) {
        return fail("line " + std::to_string(number),
                    std::to_string(cells.size()) + " values for " + std::to_string(columns.size()) +
                        " columns");
      }
      std::vector<double> values = referenceConfiguration(robot);
      for (std::size_t c = 0; c < cells.size(); ++c) {
        const Joint& joint = robot.joints[columns[c]];
        const std::string where =
            "line " + std::to_string(number) + ", column '" + joint.name + "'";
        char* end = nullptr;
        const double value = std::strtod(cells[c].c_str(), &end);
        if (cells[c].empty() || *end != '\0' || !std::isfinite(value))
          return fail(where, "'" + cells[c] + "' is not a finite number");
        if (joint.clamped(value) != value) {
          std::ostringstream limits;
          limits << "[" << joint.lower << ", " << joint.upper << "]";
          return fail(where, cells[c] + " is beyond the joint's limits " + limits.str());
        }
        values[columns[c]] = value;
      }
      frames.push_back(std::move(values));
    }
  } catch (const boost::escaped_list_error& e) {
    return fail("line " + std::to_string(number), e.what());
  }
  if (frames.empty()) return fail("line " + std::to_string(number), "no row of joint values");
  return frames;
}

Trajectory randomTrajectory(const RobotModel& robot, std::size_t frames, std::uint64_t seed) {
  PortableRandom random(seed);
  Trajectory out;
  for (std::size_t f = 0; f < frames; ++f) {
    std::vector<double> values = referenceConfiguration(robot);
    for (std::size_t j = 0; j < robot.joints.size(); ++j) {
      const Joint& joint = robot.joints[j];
      if (!joint.moves() || joint.mimics) continue;
      values[j] =
          joint.limited() ? random.uniform(joint.lower, joint.upper) : random.uniform(-M_PI, M_PI);
    }
    out.push_back(std::move(values));
  }
  return out;
}

}  // namespace collido::urdf_import
