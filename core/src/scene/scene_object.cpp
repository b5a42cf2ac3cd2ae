#include <collido/scene/scene.h>

namespace collido {

std::shared_ptr<const TriangleMesh> SceneObject::shapeAt(std::size_t frame) const {
  const std::shared_ptr<const TriangleMesh>& rest = stateMesh(stateAt(frame));
  if (!deformation) return rest;
  auto moved = std::make_shared<TriangleMesh>();
  moved->triangles = rest->triangles;
  moved->vertices = deformation->positionsAt(*rest, frame);
  return moved;
}

}  // namespace collido
