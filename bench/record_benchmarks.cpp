// collido::Recorder's cost to the application it records: one frame of a cell of 64 objects, 4
// of them moving, with 256 questions asked; the figure is the time per recorded query (frame
// time / 256), the journal's write and flush included. Target: under 1 us per query.
#include <filesystem>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include <collido/record/recorder.h>

namespace {

constexpr std::size_t kObjects = 64;
constexpr std::size_t kMoving = 4;
constexpr std::size_t kQueries = 256;
constexpr int kFramesPerRecording = 1000;  // a new recording then, so the files stay small

std::unique_ptr<collido::Recorder> newRecording(const std::string& folder,
                                                std::vector<collido::Recorder::ObjectId>& ids) {
  std::filesystem::remove_all(folder);
  auto rec = std::make_unique<collido::Recorder>(folder);
  Eigen::Matrix3Xd vertices(3, 4);
  vertices << 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1;
  Eigen::Matrix3Xi triangles(3, 4);
  triangles << 0, 0, 0, 1, 1, 2, 3, 2, 2, 3, 1, 3;
  ids.clear();
  for (std::size_t i = 0; i < kObjects; ++i)
    ids.push_back(rec->addMesh("part" + std::to_string(i), vertices, triangles));
  return rec;
}

void BM_RecordQuery(benchmark::State& state) {
  const std::string folder =
      (std::filesystem::temp_directory_path() / "collido_record_bench").string();
  std::vector<collido::Recorder::ObjectId> ids;
  std::unique_ptr<collido::Recorder> rec = newRecording(folder, ids);
  int frame = 0;
  for (auto _ : state) {
    if (++frame % kFramesPerRecording == 0) {
      state.PauseTiming();
      rec.reset();
      rec = newRecording(folder, ids);
      state.ResumeTiming();
    }
    rec->beginFrame();
    for (std::size_t m = 0; m < kMoving; ++m) {
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.translate(Eigen::Vector3d(0.001 * frame, static_cast<double>(m), 0.0));
      pose.rotate(Eigen::AngleAxisd(0.01 * frame, Eigen::Vector3d::UnitZ()));
      rec->setPose(ids[m], pose);
    }
    for (std::size_t q = 0; q < kQueries; ++q) {
      rec->ask(ids[q % kMoving], ids[kMoving + q % (kObjects - kMoving)],
               q % 8 == 0 ? collido::RecordedKind::kDistance : collido::RecordedKind::kBoolean);
    }
    rec->endFrame();
  }
  rec.reset();  // after the timed loop
  std::filesystem::remove_all(folder);
  state.SetItemsProcessed(state.iterations() * static_cast<benchmark::IterationCount>(kQueries));
  state.counters["time_per_query"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * static_cast<double>(kQueries),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_RecordQuery)->Unit(benchmark::kMicrosecond);

}  // namespace
