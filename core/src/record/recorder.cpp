#include <collido/record/recorder.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <unordered_map>
#include <vector>

#include "files.h"
#include "journal.h"

namespace collido {
namespace {

using record::numberText;
using record::PoseNumbers;

// The scene loader's coordinate range (kMaxCoordinate in collido/mesh/triangle_mesh.h).
constexpr double kMaxCoordinate = 1e18;
constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

struct Object {
  std::string name;
  std::string digest;
  PoseNumbers pose{1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  bool moved = true;  // its pose is not yet in the journal
  bool removed = false;
  std::size_t asked_in = kNone;  // the last frame that asked about it
};

struct QueryKey {
  std::size_t a;
  std::size_t b;
  RecordedKind kind;
  double tolerance;
  bool operator==(const QueryKey& o) const {
    return a == o.a && b == o.b && kind == o.kind && tolerance == o.tolerance;
  }
};

std::uint64_t mixed(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// 64 bits of the key on every platform: the hash table's, and what query_fraction samples by.
std::uint64_t keyBits(const QueryKey& k) {
  std::uint64_t bits = 0;
  static_assert(sizeof bits == sizeof k.tolerance);
  std::memcpy(&bits, &k.tolerance, sizeof bits);
  return mixed(static_cast<std::uint64_t>(k.a) * 0x9e3779b97f4a7c15ull ^
               mixed(static_cast<std::uint64_t>(k.b) + 31 * static_cast<std::uint64_t>(k.kind)) ^
               bits);
}

struct QueryKeyHash {
  std::size_t operator()(const QueryKey& k) const { return static_cast<std::size_t>(keyBits(k)); }
};

}  // namespace

struct Recorder::State {
  std::string folder;
  RecorderOptions options;
  std::ofstream journal;
  std::vector<Object> objects;
  std::map<std::string, ObjectId> by_name;
  std::unordered_map<QueryKey, std::size_t, QueryKeyHash> queries;
  std::vector<std::size_t> query_asked_in;  // by query id: the last frame that asked it
  std::string pending;                      // lines of the frame in progress, and before it
  std::vector<std::size_t> asked;           // query ids asked in the open frame
  std::size_t frames = 0;                   // completed and recorded
  std::size_t frames_seen = 0;              // completed, recorded or past max_frames
  bool frame_open = false;
  bool closed = false;

  [[noreturn]] static void refuse(const std::string& call, const std::string& problem) {
    throw RecordError("Recorder::" + call + ": " + problem);
  }

  // A call of an object or two, put into words only when it is refused: setPose and ask, the
  // calls an application makes per frame, build no string.
  struct Call {
    const char* name;
    ObjectId a = kNone;
    ObjectId b = kNone;
  };

  // "setPose(object 'arm')", "setPose(id 7)", "ask(0, 1)".
  std::string text(const Call& c) const {
    std::string out = std::string(c.name) + "(";
    if (c.b != kNone) return out + std::to_string(c.a) + ", " + std::to_string(c.b) + ")";
    if (c.a < objects.size()) return out + "object '" + objects[c.a].name + "')";
    return out + "id " + std::to_string(c.a) + ")";
  }

  [[noreturn]] void refuse(const Call& call, const std::string& problem) const {
    refuse(text(call), problem);
  }

  void expectOpen(const std::string& call) const {
    if (closed) refuse(call, "the recording is closed");
  }
  void expectOpen(const Call& call) const {
    if (closed) refuse(call, "the recording is closed");
  }

  bool recording() const { return options.max_frames == 0 || frames < options.max_frames; }

  Object& object(const Call& call, ObjectId id) {
    if (id >= objects.size()) {
      refuse(call, "unknown object id " + std::to_string(id) + " (" +
                       std::to_string(objects.size()) + " objects added)");
    }
    Object& o = objects[id];
    if (o.removed) refuse(call, "object '" + o.name + "' was removed");
    return o;
  }

  void setPose(ObjectId id, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation) {
    const Call where{"setPose", id};
    expectOpen(where);
    Object& o = object(where, id);
    if (!rotation.allFinite() || !translation.allFinite())
      refuse(where, "the pose has a NaN or infinite entry");
    const double off =
        (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (off > 1e-6 || rotation.determinant() <= 0.0) {
      refuse(where, "the rotation is not a rotation (R^T R differs from I by " + numberText(off) +
                        ", determinant " + numberText(rotation.determinant()) + ")");
    }
    if (translation.cwiseAbs().maxCoeff() > kMaxCoordinate)
      refuse(where, "the translation is beyond the coordinate range (|x| <= 1e18)");
    if (frame_open && o.asked_in == frames_seen) {
      refuse(where, "'" + o.name +
                        "' was already asked about in this frame, where it has one pose: end the "
                        "frame before moving it");
    }
    // Past the scene's 1e-9, a single-precision engine's rotation is made exactly orthonormal.
    const Eigen::Matrix3d r =
        off > 1e-9 ? Eigen::Quaterniond(rotation).normalized().toRotationMatrix() : rotation;
    PoseNumbers pose{};
    for (std::size_t row = 0; row < 3; ++row) {
      const auto i = static_cast<Eigen::Index>(row);
      for (std::size_t col = 0; col < 3; ++col)
        pose[3 * row + col] = r(i, static_cast<Eigen::Index>(col));
      pose[9 + row] = translation(i);
    }
    if (pose != o.pose) {
      o.pose = pose;
      o.moved = true;
    }
  }

  void writeFrame() {
    std::string& text = pending;
    for (std::size_t id = 0; id < objects.size(); ++id) {
      Object& o = objects[id];
      if (!o.moved) continue;
      text += "P " + std::to_string(id);
      for (const double v : o.pose)
        text += " " + numberText(v);
      text += "\n";
      o.moved = false;
    }
    text += "A";
    for (const std::size_t q : asked)
      text += " " + std::to_string(q);
    text += "\nE " + std::to_string(frames) + "\n";
    journal.write(text.data(), static_cast<std::streamsize>(text.size()));
    journal.flush();
    if (!journal) {
      closed = true;
      refuse("endFrame()", "the journal in " + folder +
                               " cannot be written: the recording has ended (collido record-close "
                               "writes the scene of the frames completed)");
    }
    text.clear();
    asked.clear();
    ++frames;
  }
};

Recorder::Recorder(const std::string& folder, RecorderOptions options)
    : state_(std::make_unique<State>()) {
  const std::string where = "Recorder('" + folder + "')";
  if (!(options.query_fraction > 0.0 && options.query_fraction <= 1.0))
    State::refuse(where, "query_fraction must be in (0, 1]");
  std::error_code error;
  std::filesystem::create_directories(folder + "/meshes", error);
  if (error) State::refuse(where, "cannot create the folder: " + error.message());
  const std::string journal = folder + "/" + record::kJournalFile;
  if (std::filesystem::exists(journal)) {
    State::refuse(
        where, "the folder already holds a recording (" + std::string(record::kJournalFile) + ")");
  }
  state_->folder = folder;
  state_->options = options;
  state_->journal.open(journal, std::ios::binary);
  state_->journal << record::kJournalHeader << "\n" << std::flush;
  if (!state_->journal) State::refuse(where, journal + " cannot be written");
}

Recorder::~Recorder() {
  if (state_->closed) return;
  try {
    close();
  } catch (const std::exception& e) {
    std::cerr << "collido::Recorder: " << e.what() << "\n";
  }
}

Recorder::ObjectId Recorder::addMesh(const std::string& name, const Eigen::Matrix3Xd& vertices,
                                     const Eigen::Matrix3Xi& triangles) {
  State& s = *state_;
  const std::string where = "addMesh('" + name + "')";
  s.expectOpen(where);
  if (const std::string problem = record::nameProblem(name); !problem.empty())
    State::refuse(where, problem);
  if (triangles.cols() == 0) State::refuse(where, "the mesh has no triangles");
  for (Eigen::Index v = 0; v < vertices.cols(); ++v) {
    if (!vertices.col(v).allFinite() || vertices.col(v).cwiseAbs().maxCoeff() > kMaxCoordinate) {
      State::refuse(where, "vertex " + std::to_string(v) +
                               " is not finite or beyond the coordinate range (|x| <= 1e18)");
    }
  }
  if (triangles.minCoeff() < 0 || triangles.maxCoeff() >= vertices.cols()) {
    State::refuse(
        where, "a triangle's vertex index is outside [0, " + std::to_string(vertices.cols()) + ")");
  }
  const std::string digest = record::meshDigest(vertices, triangles);
  if (const auto found = s.by_name.find(name); found != s.by_name.end()) {
    if (s.objects[found->second].removed) {
      State::refuse(where, "'" + name +
                               "' was removed, and a scene's object exists in one span of frames: "
                               "add it again under another name");
    }
    if (s.objects[found->second].digest != digest) {
      State::refuse(where, "'" + name +
                               "' was added with another mesh (other vertices or "
                               "triangles): a name stands for one mesh");
    }
    return found->second;
  }
  const std::string file = "meshes/" + digest + ".ply";
  // Past max_frames nothing more is written: the object is only checked.
  if (s.recording() && !std::filesystem::exists(s.folder + "/" + file))
    record::writeFileAtomically(s.folder + "/" + file, record::plyBytes(vertices, triangles));
  const ObjectId id = s.objects.size();
  s.objects.push_back(Object{name, digest});
  s.by_name.emplace(name, id);
  if (s.recording()) s.pending += "O " + std::to_string(id) + " " + file + " " + name + "\n";
  return id;
}

void Recorder::removeObject(ObjectId id) {
  State& s = *state_;
  const State::Call where{"removeObject", id};
  s.expectOpen(where);
  Object& o = s.object(where, id);
  o.removed = true;
  // Gone at once: it exists in the open frame only if that frame asked about it already.
  const bool asked_now = s.frame_open && o.asked_in == s.frames_seen;
  const long long last = static_cast<long long>(s.frames) - (asked_now ? 0 : 1);
  if (s.recording()) s.pending += "X " + std::to_string(id) + " " + std::to_string(last) + "\n";
}

void Recorder::beginFrame() {
  State& s = *state_;
  s.expectOpen("beginFrame()");
  if (s.frame_open) State::refuse("beginFrame()", "a frame is open: call endFrame() first");
  s.frame_open = true;
}

void Recorder::setPose(ObjectId id, const Eigen::Isometry3d& pose) {
  state_->setPose(id, pose.linear(), pose.translation());
}

void Recorder::setPose(ObjectId id, const Eigen::Matrix4d& matrix) {
  if (matrix.row(3) != Eigen::RowVector4d(0, 0, 0, 1)) {
    state_->refuse(State::Call{"setPose", id},
                   "a 4 x 4 pose's bottom row must be (0, 0, 0, 1), as a rigid transform's is");
  }
  state_->setPose(id, matrix.topLeftCorner<3, 3>(), matrix.topRightCorner<3, 1>());
}

void Recorder::setPose(ObjectId id, const Eigen::Matrix<double, 3, 4>& matrix) {
  state_->setPose(id, matrix.leftCols<3>(), matrix.col(3));
}

void Recorder::ask(ObjectId a, ObjectId b, RecordedKind kind, double abs_tolerance) {
  State& s = *state_;
  const State::Call where{"ask", a, b};
  s.expectOpen(where);
  if (!s.frame_open) s.refuse(where, "no frame is open: call beginFrame() first");
  Object& oa = s.object(where, a);
  Object& ob = s.object(where, b);
  if (a == b) s.refuse(where, "a query needs two different objects");
  if (!(abs_tolerance >= 0.0) || !std::isfinite(abs_tolerance))
    s.refuse(where, "the tolerance must be finite and >= 0");
  if (abs_tolerance > 0.0 && kind != RecordedKind::kDistance)
    s.refuse(where, "a tolerance applies to distance queries only");
  oa.asked_in = ob.asked_in = s.frames_seen;
  if (!s.recording()) return;
  const QueryKey key{a, b, kind, abs_tolerance + 0.0};  // -0 is 0, to the hash too
  auto found = s.queries.find(key);
  if (found == s.queries.end()) {
    const double fraction = s.options.query_fraction;
    if (fraction < 1.0 && static_cast<double>(keyBits(key) >> 11) * 0x1p-53 >= fraction) return;
    const std::size_t id = s.queries.size();
    found = s.queries.emplace(key, id).first;
    s.query_asked_in.push_back(kNone);
    s.pending += "Q " + std::to_string(id) + " " + std::to_string(a) + " " + std::to_string(b) +
                 " " + record::kindName(kind) + " " + numberText(abs_tolerance) + "\n";
  }
  // A question asked twice in a frame is one query of that frame.
  if (s.query_asked_in[found->second] == s.frames) return;
  s.query_asked_in[found->second] = s.frames;
  s.asked.push_back(found->second);
}

void Recorder::endFrame() {
  State& s = *state_;
  s.expectOpen("endFrame()");
  if (!s.frame_open) State::refuse("endFrame()", "no frame is open: call beginFrame() first");
  s.frame_open = false;
  if (s.recording()) s.writeFrame();
  ++s.frames_seen;
}

void Recorder::close() {
  State& s = *state_;
  s.expectOpen("close()");
  s.closed = true;
  s.journal.close();
  closeRecording(s.folder);
}

std::size_t Recorder::framesRecorded() const {
  return state_->frames;
}

const std::string& Recorder::folder() const {
  return state_->folder;
}

}  // namespace collido
