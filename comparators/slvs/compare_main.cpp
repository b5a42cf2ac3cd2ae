// collido_slvs_comparison: Collidoscope's least-change solver against SolveSpace's (libslvs) on
// the same point chains, measured in one run: success rate, how far each solver's change is
// above the exact minimum, and time per solve, at 6 to 3,000 parameters.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "point_chain.h"
#include "solvers.h"

namespace collido::slvs_comparison {
namespace {

/// A solution meets the constraints when every residual is below this (lengths are ~1).
constexpr double kMet = 1e-9;
/// Ours must be the exact minimum-change solution: first-order conditions to this, relative.
constexpr double kExact = 1e-9;

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

struct Timed {
  Solution solution;
  double seconds = 0.0;
};

template <typename Solver>
Timed timed(Solver solver, const PointChain& chain) {
  const auto begin = std::chrono::steady_clock::now();
  Timed result{solver(chain), 0.0};
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  return result;
}

struct Row {
  int points = 0;
  int instances = 0;
  int ours_met = 0;
  int ours_missed = 0;  ///< instances libslvs solved and ours did not: solvable, so a failure
  int slvs_met = 0;
  int slvs_okay = 0;               ///< libslvs reported success (by its own tolerance)
  double slvs_okay_error = 0.0;    ///< the worst constraint error among those
  double ours_stationarity = 0.0;  ///< the worst over our solutions
  std::vector<double> extra;       ///< slvs' change over ours, relative, where both solved
  std::vector<double> ours_seconds;
  std::vector<double> slvs_seconds;
  std::vector<std::string> slvs_failures;
};

Row compare(int points, const std::vector<double>& drags, int seeds) {
  Row row;
  row.points = points;
  for (double drag : drags) {
    for (int seed = 1; seed <= seeds; ++seed) {
      const PointChain chain = makePointChain(points, drag, static_cast<std::uint64_t>(seed));
      const Timed ours = timed(solveWithCollidoscope, chain);
      const Timed slvs = timed(solveWithSlvs, chain);
      ++row.instances;
      row.ours_seconds.push_back(ours.seconds);
      row.slvs_seconds.push_back(slvs.seconds);
      const bool ours_met =
          ours.solution.solved && constraintError(chain, ours.solution.points) < kMet;
      const bool slvs_met =
          slvs.solution.solved && constraintError(chain, slvs.solution.points) < kMet;
      if (slvs.solution.solved) {
        ++row.slvs_okay;
        row.slvs_okay_error =
            std::max(row.slvs_okay_error, constraintError(chain, slvs.solution.points));
      }
      row.ours_met += ours_met ? 1 : 0;
      row.ours_missed += !ours_met && slvs.solution.solved ? 1 : 0;
      row.slvs_met += slvs_met ? 1 : 0;
      if (!slvs_met) {
        row.slvs_failures.push_back(slvs.solution.solved ? "constraints not met"
                                                         : slvs.solution.failure);
      }
      if (ours_met) {
        row.ours_stationarity =
            std::max(row.ours_stationarity, stationarityError(chain, ours.solution.points));
      }
      // The change is compared wherever libslvs reported success: its answers meet the
      // constraints to its own tolerance (a few 1e-9), far below the changes compared.
      if (ours_met && slvs.solution.solved) {
        const double exact = change(chain, ours.solution.points);
        row.extra.push_back(change(chain, slvs.solution.points) / exact - 1.0);
      }
    }
  }
  return row;
}

}  // namespace
}  // namespace collido::slvs_comparison

int main(int argc, char** argv) {
  using namespace collido::slvs_comparison;
  CLI::App app{"Collidoscope's least-change constraint solver against SolveSpace's libslvs"};
  std::vector<int> points = {2, 20, 200, 1000};
  std::vector<double> drags = {0.05, 0.2, 0.5, 1.0, 2.0};
  int seeds = 4;
  std::string json_path;
  app.add_option("--points", points, "chain lengths (3 parameters a point)");
  app.add_option("--drags", drags, "how far the last point is dragged");
  app.add_option("--seeds", seeds, "random chains per drag")->check(CLI::PositiveNumber);
  app.add_option("--json", json_path, "also write the rows as JSON here");
  CLI11_PARSE(app, argc, argv);

  nlohmann::json rows = nlohmann::json::array();
  bool exact = true;  // the target: the exact minimum on every solvable problem
  std::printf("%10s %9s %11s %11s %9s %12s %13s %12s %12s %11s %11s %7s\n", "parameters",
              "instances", "ours met", "slvs met", "slvs OK", "slvs OK err", "ours KKT err",
              "slvs extra", "slvs extra", "ours", "slvs", "speed-up");
  std::printf("%10s %9s %11s %11s %9s %12s %13s %12s %12s %11s %11s %7s\n", "", "", "", "", "",
              "(worst)", "(worst)", "(median)", "(worst)", "(median)", "(median)", "");
  for (int n : points) {
    const Row row = compare(n, drags, seeds);
    const double ours_time = median(row.ours_seconds);
    const double slvs_time = median(row.slvs_seconds);
    const double worst_extra =
        row.extra.empty() ? 0.0 : *std::max_element(row.extra.begin(), row.extra.end());
    std::printf(
        "%10d %9d %5d (%3.0f%%) %5d (%3.0f%%) %9d %12.1e %13.2e %11.3f%% %11.3f%% %8.3f ms "
        "%8.3f ms %6.1fx\n",
        3 * n, row.instances, row.ours_met, 100.0 * row.ours_met / row.instances, row.slvs_met,
        100.0 * row.slvs_met / row.instances, row.slvs_okay, row.slvs_okay_error,
        row.ours_stationarity, 100.0 * median(row.extra), 100.0 * worst_extra, 1e3 * ours_time,
        1e3 * slvs_time, slvs_time / ours_time);
    exact = exact && row.ours_missed == 0 && row.ours_stationarity <= kExact;
    rows.push_back({{"parameters", 3 * n},
                    {"instances", row.instances},
                    {"ours_met", row.ours_met},
                    {"ours_missed", row.ours_missed},
                    {"slvs_met", row.slvs_met},
                    {"slvs_okay", row.slvs_okay},
                    {"slvs_okay_worst_error", row.slvs_okay_error},
                    {"ours_worst_stationarity_error", row.ours_stationarity},
                    {"slvs_extra_change", row.extra},
                    {"ours_seconds", row.ours_seconds},
                    {"slvs_seconds", row.slvs_seconds},
                    {"slvs_failures", row.slvs_failures}});
  }
  if (!json_path.empty()) std::ofstream(json_path) << rows.dump(1) << "\n";
  if (!exact) {
    std::printf("FAILED: ours missed a problem libslvs solved, or a first-order error above %g\n",
                kExact);
    return 1;
  }
  return 0;
}
