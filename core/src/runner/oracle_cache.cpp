// The oracle's answers of one scene, computed once and shared; its fingerprint says which
// scene they belong to, so answers kept on disk are never reused for another.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <type_traits>

#include <collido/motion.h>
#include <collido/runner/digest.h>
#include <collido/runner/runner.h>

namespace collido {

const OracleAnswer& OracleCache::get(std::size_t ia, std::size_t ib, std::size_t frame,
                                     bool distance) {
  const auto key = std::make_tuple(ia, ib, frame);
  const SceneObject& a = scene_.objects[ia];
  const SceneObject& b = scene_.objects[ib];
  auto found = answers_.find(key);
  if (found == answers_.end()) {
    // Boolean queries need only a witness; a pair that any all-pairs query also names shares the
    // full answer, which contains the boolean one.
    const bool needs_all =
        !witness_only_ &&
        std::any_of(scene_.queries.begin(), scene_.queries.end(), [&](const SceneQuery& q) {
          return queryKindInfo(q.request.kind).oracle == OracleNeed::kAllPairs &&
                 (q.isGroup() ? q.asksPair(ia, ib) : q.a == ia && q.b == ib);
        });
    found = answers_
                .emplace(key,
                         exactIntersectingPairs(
                             *a.shapeAt(frame), a.poseAt(frame), *b.shapeAt(frame), b.poseAt(frame),
                             needs_all ? OracleMode::kAllPairs : OracleMode::kFirstPair))
                .first;
    ++computed_;
  }
  if (distance && !found->second.distance) {
    ++computed_;
    found->second.distance =
        exactMeshDistance(*a.shapeAt(frame), a.poseAt(frame), *b.shapeAt(frame), b.poseAt(frame));
  }
  return found->second;
}

const OracleAnswer& OracleCache::getStep(std::size_t ia, std::size_t ib, std::size_t frame,
                                         double width) {
  get(ia, ib, frame);
  OracleAnswer& answer = answers_.at(std::make_tuple(ia, ib, frame));
  if (answer.first_contact && answer.first_contact_width <= width) return answer;
  const SceneObject& a = scene_.objects[ia];
  const SceneObject& b = scene_.objects[ib];
  // The scene reader has made sure both poses are rigid and the frame after exists.
  const auto motion = [&](const SceneObject& o) {
    return StepMotion::between(o.poseAt(frame), o.poseAt(frame + 1), o.name).value();
  };
  ++computed_;
  answer.first_contact =
      exactFirstContact(*a.shapeAt(frame), motion(a), *b.shapeAt(frame), motion(b), width);
  answer.first_contact_width = width;
  return answer;
}

const OracleAnswer& OracleCache::answerFor(const SceneQuery& query, std::size_t a, std::size_t b,
                                           std::size_t frame, bool distances) {
  switch (queryKindInfo(query.request.kind).oracle) {
    case OracleNeed::kDistance:
      return get(a, b, frame, distances);
    case OracleNeed::kFirstContact:
      return getStep(a, b, frame, query.request.step->bracket_width);
    case OracleNeed::kWitness:
    case OracleNeed::kAllPairs:
      break;
  }
  return get(a, b, frame);
}

std::string OracleCache::fingerprint() const {
  Digest d;
  d.value(witness_only_);
  d.value(scene_.frames);
  d.value(scene_.objects.size());
  const auto shape = [&d](const TriangleMesh& mesh) {
    d.value(mesh.vertices.cols());
    d.bytes(mesh.vertices.data(), sizeof(double) * static_cast<std::size_t>(mesh.vertices.size()));
    d.value(mesh.triangles.cols());
    d.bytes(mesh.triangles.data(), sizeof(int) * static_cast<std::size_t>(mesh.triangles.size()));
  };
  for (const SceneObject& o : scene_.objects) {
    shape(*o.mesh);
    // A changing shape: every frame's (states and movable nodes).
    d.value(o.changesShape());
    if (o.changesShape()) {
      for (std::size_t f = 0; f < scene_.frames; ++f)
        shape(*o.shapeAt(f));
    }
    d.value(o.poses.size());
    for (const Pose& pose : o.poses)
      d.bytes(pose.matrix().data(), sizeof(double) * 16);
  }
  d.value(scene_.queries.size());
  for (const SceneQuery& q : scene_.queries) {
    d.value(q.request.kind);
    d.value(q.a);
    d.value(q.b);
    d.value(q.among.size());
    for (std::size_t index : q.among)
      d.value(index);
    d.value(q.side_b.size());
    for (std::size_t index : q.side_b)
      d.value(index);
    // Only when given, so that the stored answers of scenes without it keep their digests.
    if (!q.except.empty()) d.value(q.except.size());
    if (queryKindInfo(q.request.kind).over_a_step) d.value(q.request.step->bracket_width);
    for (const auto& [i, j] : q.except) {
      d.value(i);
      d.value(j);
    }
  }
  return d.hex();
}

std::string OracleCache::inputSizes() const {
  std::string sizes = "frames " + std::to_string(scene_.frames) + ", queries " +
                      std::to_string(scene_.queries.size()) + ", objects";
  for (const SceneObject& o : scene_.objects) {
    sizes += " " + std::to_string(o.mesh->vertices.cols()) + "v " +
             std::to_string(o.mesh->triangles.cols()) + "t " + std::to_string(o.poses.size()) +
             "p" + (o.changesShape() ? " changing" : "");
  }
  return sizes;
}

}  // namespace collido
