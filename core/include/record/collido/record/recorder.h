// Records an application's own collision queries as a Collidoscope scene: the meshes it loads,
// its objects' poses frame by frame and the questions it asks, so that `collido study` can replay
// that workload on every backend against the exact oracle. Depends on the standard library and
// Eigen only, so it drops into an application built against any collision library.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace collido {

/// The question a recorded query asks (the scene's query kinds, scenes/README.md).
enum class RecordedKind { kBoolean, kAllPairs, kContacts, kDistance };

/// Bounds that keep a long recording small.
struct RecorderOptions {
  /// Frames recorded at most (0: no limit; a scene loads at most 1,000,000 frames); later
  /// frames, and objects added in them, are checked but not recorded.
  std::size_t max_frames = 0;
  /// The share of asked object pairs recorded, in (0, 1]. A pair is chosen by a hash of the two
  /// objects and the question, so a kept pair is kept in every frame it is asked.
  double query_fraction = 1.0;
};

/// A Recorder call refused: the message names the call and the problem. A refused call changed
/// nothing and the recording goes on, except for a journal that cannot be written (endFrame) and
/// close(), which end the recording.
class RecordError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// Records into a folder: meshes/ (binary PLY in double precision, each distinct mesh once),
/// journal.txt (every completed frame, appended and flushed as it ends) and, when closed,
/// scene.json. A process that dies mid-run leaves the frames it completed in the journal, which
/// `collido record-close FOLDER` (or closeRecording) turns into the scene.
///
/// A frame is beginFrame(), setPose() and ask() calls, endFrame(). A pose set outside a frame
/// holds from the next frame on; an object keeps its pose until set again (identity at first).
/// An object exists from the frame it is added in (or the next one) until removeObject(). Not
/// thread-safe: one thread records.
class Recorder {
 public:
  using ObjectId = std::size_t;

  /// Creates `folder` (and its parents) for a new recording. Throws RecordError when the folder
  /// already holds a recording or cannot be written.
  explicit Recorder(const std::string& folder, RecorderOptions options = {});
  /// Ends the recording as close() does; an open frame is dropped (it never completed). Errors
  /// are written to standard error, since a destructor cannot throw.
  ~Recorder();
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  /// Adds an object named `name` (UTF-8, no control characters, no surrounding spaces) with a
  /// mesh: 3 x V vertices, 3 x T triangles of vertex indices. Identical meshes are stored once,
  /// by content. Adding a name again with the same mesh returns its id; with another mesh, or
  /// after it was removed, it is refused.
  ObjectId addMesh(const std::string& name, const Eigen::Matrix3Xd& vertices,
                   const Eigen::Matrix3Xi& triangles);
  /// The object no longer exists: from the open frame on, or from the next one if the open frame
  /// asked about it already. It may not be posed or asked again.
  void removeObject(ObjectId id);

  void beginFrame();
  /// The object's pose (world = rotation * model + translation). A rotation within 1e-6 of
  /// orthonormal is kept (made exactly orthonormal past 1e-9, as single-precision engines need);
  /// a NaN, a non-rotation or a translation beyond 1e18 is refused. An object already asked in
  /// this frame cannot move in it: a frame has one pose per object.
  void setPose(ObjectId id, const Eigen::Isometry3d& pose);
  void setPose(ObjectId id, const Eigen::Matrix4d& matrix);  ///< bottom row (0, 0, 0, 1)
  void setPose(ObjectId id, const Eigen::Matrix<double, 3, 4>& matrix);
  /// Records that the application asked `kind` of objects `a` and `b` in this frame;
  /// `abs_tolerance` (distance only, >= 0): the answer may exceed the true distance by it.
  void ask(ObjectId a, ObjectId b, RecordedKind kind, double abs_tolerance = 0.0);
  void endFrame();

  /// Writes scene.json from the frames completed and ends the recording (later calls are
  /// refused), even when it throws: RecordError when no frame was completed or no query asked
  /// (there is no scene to write), or when the scene cannot be written.
  void close();

  std::size_t framesRecorded() const;
  const std::string& folder() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// Writes FOLDER/scene.json from FOLDER/journal.txt: every frame completed, a frame cut short
/// left out. Returns the number of frames. Throws RecordError naming the file and line of a
/// journal it cannot read, or when there is no complete frame or no query.
std::size_t closeRecording(const std::string& folder);

}  // namespace collido
