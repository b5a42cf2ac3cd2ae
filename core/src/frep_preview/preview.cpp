// Preview pictures of FRep solids: interval ray casting with an orthographic camera, and PNG
// output through libpng.
#include <collido/frep_preview/preview.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <png.h>

namespace collido::frep {
namespace {

struct Ray {
  Eigen::Vector3d origin;
  Eigen::Vector3d direction;  // unit
};

// The segment of the ray inside a box (slab test), or nothing.
std::optional<std::pair<double, double>> clip(const Ray& ray, const Eigen::AlignedBox3d& box) {
  double near = 0.0;
  double far = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    if (ray.direction[i] == 0.0) {
      if (ray.origin[i] < box.min()[i] || ray.origin[i] > box.max()[i]) return std::nullopt;
      continue;
    }
    double t0 = (box.min()[i] - ray.origin[i]) / ray.direction[i];
    double t1 = (box.max()[i] - ray.origin[i]) / ray.direction[i];
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
  }
  if (near > far) return std::nullopt;
  return std::make_pair(near, far);
}

IntervalBox segmentBox(const Ray& ray, double t0, double t1) {
  IntervalBox box;
  for (int i = 0; i < 3; ++i) {
    const double a = ray.origin[i] + t0 * ray.direction[i];
    const double b = ray.origin[i] + t1 * ray.direction[i];
    // Widened by a relative ulp-scale margin: the end points carry rounding.
    const double margin = 1e-12 * (std::abs(a) + std::abs(b) + 1e-300);
    box.axis[i] = Interval(std::min(a, b) - margin, std::max(a, b) + margin);
  }
  return box;
}

// The first t in [t0, t1] where f >= 0, to within `resolution`, or nothing.
std::optional<double> firstHit(const Solid& solid, const Ray& ray, double t0, double t1,
                               double resolution) {
  if (solid.range(segmentBox(ray, t0, t1)).upper() < 0.0) return std::nullopt;
  if (t1 - t0 <= resolution) {
    // Somewhere here f may reach 0: bisect on the sign where the ends differ, else take the end
    // that is inside (or the start, for a feature thinner than the resolution).
    const auto inside = [&](double t) { return solid.value(ray.origin + t * ray.direction) >= 0; };
    if (inside(t0)) return t0;
    if (!inside(t1)) return std::nullopt;
    double lo = t0;
    double hi = t1;
    for (int k = 0; k < 20; ++k) {
      const double mid = 0.5 * (lo + hi);
      (inside(mid) ? hi : lo) = mid;
    }
    return hi;
  }
  const double mid = 0.5 * (t0 + t1);
  if (auto hit = firstHit(solid, ray, t0, mid, resolution)) return hit;
  return firstHit(solid, ray, mid, t1, resolution);
}

Eigen::Vector3d gradient(const Solid& solid, const Eigen::Vector3d& p, double h) {
  Eigen::Vector3d g;
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d step = Eigen::Vector3d::Zero();
    step[i] = h;
    g[i] = (solid.value(p + step) - solid.value(p - step)) / (2 * h);
  }
  return g;
}

std::uint8_t channel(double v) {
  return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(v, 0.0, 1.0)));
}

}  // namespace

Result<Image> renderPreview(const std::vector<PreviewSolid>& solids,
                            const std::optional<Eigen::Vector3d>& marker,
                            const PreviewOptions& options) {
  if (options.width < 1 || options.height < 1 || options.width > 8192 || options.height > 8192)
    return Status(StatusCode::kInvalidArgument, "preview: image size must be 1..8192 pixels");
  if (!(options.view_direction.norm() > 0) || !options.view_direction.allFinite())
    return Status(StatusCode::kInvalidArgument, "preview: view direction must be non-zero");
  Eigen::AlignedBox3d scene;
  std::vector<Eigen::AlignedBox3d> bounds;
  for (const PreviewSolid& item : solids) {
    Eigen::AlignedBox3d box = item.solid->bounds();
    const bool finite = !box.isEmpty() && box.min().allFinite() && box.max().allFinite();
    if (finite) scene.extend(box);
    bounds.push_back(box);
  }
  if (scene.isEmpty())
    return Status(StatusCode::kInvalidArgument, "preview: no solid has finite, non-empty bounds");
  // Unbounded solids are drawn inside the finite ones' frame.
  for (Eigen::AlignedBox3d& box : bounds)
    box = box.isEmpty() ? box : box.intersection(scene);

  const Eigen::Vector3d forward = options.view_direction.normalized();
  Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ());
  if (right.norm() < 1e-9) right = forward.cross(Eigen::Vector3d::UnitY());
  right.normalize();
  const Eigen::Vector3d up = right.cross(forward);
  const Eigen::Vector3d centre = scene.center();
  const double radius = 0.5 * scene.sizes().norm();
  const double aspect = static_cast<double>(options.width) / options.height;
  const double half_height = 1.05 * radius * std::max(1.0, 1.0 / aspect);
  const double pixel = 2 * half_height / options.height;
  const Eigen::Vector3d light = (-forward + 0.6 * up + 0.4 * right).normalized();

  Image image;
  image.width = options.width;
  image.height = options.height;
  image.rgb.resize(static_cast<std::size_t>(3) * options.width * options.height);
  for (int y = 0; y < options.height; ++y) {
    for (int x = 0; x < options.width; ++x) {
      const double u = (x + 0.5 - 0.5 * options.width) * pixel;
      const double v = (0.5 * options.height - y - 0.5) * pixel;
      const Ray ray{centre + u * right + v * up - 2 * radius * forward, forward};
      double nearest = std::numeric_limits<double>::infinity();
      std::size_t which = solids.size();
      for (std::size_t s = 0; s < solids.size(); ++s) {
        if (bounds[s].isEmpty()) continue;
        const auto span = clip(ray, bounds[s]);
        if (!span) continue;
        const auto hit = firstHit(*solids[s].solid, ray, span->first,
                                  std::min(span->second, nearest), 0.25 * pixel);
        if (hit && *hit < nearest) {
          nearest = *hit;
          which = s;
        }
      }
      // A soft vertical gradient behind the solids.
      Eigen::Vector3d colour = Eigen::Vector3d::Constant(0.93 - 0.12 * y / options.height);
      if (which < solids.size()) {
        const Eigen::Vector3d p = ray.origin + nearest * ray.direction;
        Eigen::Vector3d normal = -gradient(*solids[which].solid, p, 0.05 * pixel);
        normal = normal.norm() > 0 ? normal.normalized() : Eigen::Vector3d(-forward);
        const double diffuse = std::max(0.0, normal.dot(light));
        colour = solids[which].colour * (0.25 + 0.75 * diffuse);
      }
      const std::size_t at = 3 * (static_cast<std::size_t>(y) * options.width + x);
      for (int c = 0; c < 3; ++c)
        image.rgb[at + c] = channel(colour[c]);
    }
  }
  if (marker) {
    const Eigen::Vector3d d = *marker - centre;
    const double mx = d.dot(right) / pixel + 0.5 * options.width;
    const double my = 0.5 * options.height - d.dot(up) / pixel;
    const double dot = std::max(3.0, options.height / 60.0);
    for (int y = 0; y < options.height; ++y) {
      for (int x = 0; x < options.width; ++x) {
        const double r = std::hypot(x + 0.5 - mx, y + 0.5 - my);
        if (r > dot) continue;
        const std::size_t at = 3 * (static_cast<std::size_t>(y) * options.width + x);
        const bool rim = r > dot - 1.2;
        image.rgb[at] = rim ? 255 : 220;
        image.rgb[at + 1] = rim ? 255 : 30;
        image.rgb[at + 2] = rim ? 255 : 30;
      }
    }
  }
  return image;
}

Result<std::string> encodePng(const Image& image) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  // The first call measures, the second writes.
  png_alloc_size_t size = 0;
  if (png_image_write_to_memory(&png, nullptr, &size, 0, image.rgb.data(), 0, nullptr) != 0) {
    std::string bytes(size, '\0');
    if (png_image_write_to_memory(&png, bytes.data(), &size, 0, image.rgb.data(), 0, nullptr) !=
        0) {
      bytes.resize(size);
      return bytes;
    }
  }
  const std::string why = png.message;
  png_image_free(&png);
  return Status(StatusCode::kInternal, "cannot encode the PNG picture: " + why);
}

}  // namespace collido::frep
