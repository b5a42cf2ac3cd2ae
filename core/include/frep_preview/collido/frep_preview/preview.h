#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <collido/frep/solid.h>
#include <collido/status.h>

namespace collido::frep {

/// An 8-bit RGB image, rows top to bottom.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  ///< 3 bytes per pixel
};

/// A solid to draw and its colour (0..1 per channel).
struct PreviewSolid {
  const Solid* solid = nullptr;
  Eigen::Vector3d colour = Eigen::Vector3d(0.7, 0.7, 0.7);
};

/// The camera and the picture's size.
struct PreviewOptions {
  int width = 320;
  int height = 240;
  /// Direction the camera looks along (world frame); z is up in the picture.
  Eigen::Vector3d view_direction = Eigen::Vector3d(-1.0, -0.8, -0.6);
};

/// Ray-casts the solids with an orthographic camera framing their bounds: along each pixel's ray
/// the first point of each solid is found by interval subdivision of the ray (a segment is skipped
/// only where the interval of f proves it outside, so nothing thicker than a fraction of a pixel
/// is missed), then refined by bisection and shaded by the gradient of f. `marker` (a collision
/// witness, say) is drawn as a red dot on top. Fails when no solid has finite bounds.
Result<Image> renderPreview(const std::vector<PreviewSolid>& solids,
                            const std::optional<Eigen::Vector3d>& marker,
                            const PreviewOptions& options);

/// The image as the bytes of a PNG file (libpng).
Result<std::string> encodePng(const Image& image);

}  // namespace collido::frep
