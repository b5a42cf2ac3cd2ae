// The FRep operations: perturbation, set operations (min/max and R-functions), offset, affine
// transforms, twisting, morphing, sweeping along a path and projection along an axis.
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/LU>

#include <collido/frep/solid.h>

#include "bounds_util.h"

namespace collido::frep {
namespace {

using boost::numeric::square;
using detail::emptyBox;
using detail::infiniteBox;
using detail::isFinite;

using detail::require;

void requireSolid(const SolidPtr& solid, const char* operation) {
  require(solid != nullptr, std::string(operation) + " needs a solid");
}

// ---- perturbation --------------------------------------------------------------------------

double bumpValue(const Bump& bump, const Eigen::Vector3d& p) {
  const double s = ((p - bump.centre) / bump.radius).squaredNorm();
  if (s >= 1.0) return 0.0;
  const double t = 1.0 - s;
  return bump.amplitude * t * t * t;
}

// The bump's ball's bounding box, rounded outward: outside it the bump is exactly 0.
Eigen::AlignedBox3d reachOf(const Bump& bump) {
  Eigen::AlignedBox3d box;
  for (int i = 0; i < 3; ++i) {
    box.min()[i] = OutwardRounding::down(bump.centre[i] - bump.radius);
    box.max()[i] = OutwardRounding::up(bump.centre[i] + bump.radius);
  }
  return box;
}

Interval bumpRange(const Bump& bump, const Eigen::AlignedBox3d& reach, const IntervalBox& box) {
  // Zero wherever the box misses the ball's bounding box: skips most bumps of a busy solid.
  for (int i = 0; i < 3; ++i) {
    if (box.axis[i].lower() >= reach.max()[i] || box.axis[i].upper() <= reach.min()[i])
      return Interval(0.0);
  }
  Interval s(0.0);
  for (int i = 0; i < 3; ++i)
    s += square((box.axis[i] - bump.centre[i]) / bump.radius);
  const Interval t = 1.0 - s;
  // (1 - s)^3 is 0 for s >= 1: clamp before the cube, which is monotone on t >= 0.
  const Interval clamped(std::max(0.0, t.lower()), std::max(0.0, t.upper()));
  return bump.amplitude * boost::numeric::pow(clamped, 3);
}

class Perturbed final : public Solid {
 public:
  Perturbed(SolidPtr solid, std::vector<Bump> bumps)
      : solid_(std::move(solid)), bumps_(std::move(bumps)) {
    for (const Bump& bump : bumps_) {
      if (bump.amplitude > 0) raise_ = OutwardRounding::up(raise_ + bump.amplitude);
      reaches_.push_back(reachOf(bump));
    }
  }
  double value(const Eigen::Vector3d& p) const override {
    double f = solid_->value(p);
    for (const Bump& bump : bumps_)
      f += bumpValue(bump, p);
    return f;
  }
  Interval range(const IntervalBox& box) const override {
    Interval f = solid_->range(box);
    for (std::size_t i = 0; i < bumps_.size(); ++i)
      f += bumpRange(bumps_[i], reaches_[i], box);
    return f;
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    // Outside every raising bump f itself reaches the level; inside one, f reaches the level
    // less the sum of the raising amplitudes (overlapping bumps add up).
    Eigen::AlignedBox3d box = solid_->superlevelBounds(level);
    if (raise_ == 0.0) return box;
    const Eigen::AlignedBox3d lowered = solid_->superlevelBounds(detail::levelDown(level, raise_));
    for (std::size_t i = 0; i < bumps_.size(); ++i) {
      if (bumps_[i].amplitude > 0)
        box = detail::unionOf(box, detail::intersectionOf(reaches_[i], lowered));
    }
    return box;
  }

 private:
  SolidPtr solid_;
  std::vector<Bump> bumps_;
  std::vector<Eigen::AlignedBox3d> reaches_;
  double raise_ = 0.0;
};

// ---- set operations ------------------------------------------------------------------------

enum class SetKind { kUnion, kIntersection };

double combine(SetKind kind, SetBlend blend, double a, double b) {
  if (blend == SetBlend::kMinMax) return kind == SetKind::kUnion ? std::max(a, b) : std::min(a, b);
  const double root = std::sqrt(a * a + b * b);
  return kind == SetKind::kUnion ? a + b + root : a + b - root;
}

Interval combine(SetKind kind, SetBlend blend, const Interval& a, const Interval& b) {
  if (blend == SetBlend::kMinMax) return kind == SetKind::kUnion ? maxOf(a, b) : minOf(a, b);
  const Interval root = sqrt(square(a) + square(b));
  return kind == SetKind::kUnion ? a + b + root : a + b - root;
}

// A binary set operation; n-ary ones fold into a left-leaning chain.
class SetOperation final : public Solid {
 public:
  SetOperation(SetKind kind, SetBlend blend, SolidPtr a, SolidPtr b, bool complement_b)
      : kind_(kind),
        blend_(blend),
        a_(std::move(a)),
        b_(std::move(b)),
        complement_b_(complement_b) {}
  double value(const Eigen::Vector3d& p) const override {
    const double fb = b_->value(p);
    return combine(kind_, blend_, a_->value(p), complement_b_ ? -fb : fb);
  }
  Interval range(const IntervalBox& box) const override {
    const Interval fb = b_->range(box);
    return combine(kind_, blend_, a_->range(box), complement_b_ ? -fb : fb);
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    if (complement_b_) return a_->superlevelBounds(level);  // a difference lies inside a
    if (kind_ == SetKind::kIntersection) {
      // min and the R-intersection are both at most min(f1, f2).
      return detail::intersectionOf(a_->superlevelBounds(level), b_->superlevelBounds(level));
    }
    // The R-union is at most 4 max(f1, f2) where that is >= 0, and at most
    // (2 - sqrt 2) max(f1, f2) where both are negative.
    double reach = level;
    if (blend_ == SetBlend::kRFunction)
      reach = level > 0 ? level / 4 : level / (2 - std::sqrt(2.0));
    return detail::unionOf(a_->superlevelBounds(reach), b_->superlevelBounds(reach));
  }

 private:
  SetKind kind_;
  SetBlend blend_;
  SolidPtr a_;
  SolidPtr b_;
  bool complement_b_;
};

SolidPtr fold(SetKind kind, std::vector<SolidPtr> operands, SetBlend blend, const char* name) {
  require(!operands.empty(), std::string(name) + " needs at least one operand");
  for (const SolidPtr& operand : operands)
    requireSolid(operand, name);
  SolidPtr result = operands.front();
  for (std::size_t i = 1; i < operands.size(); ++i)
    result = std::make_shared<SetOperation>(kind, blend, result, operands[i], false);
  return result;
}

// ---- offset, transform, twist, morph ---------------------------------------------------------

class Offset final : public Solid {
 public:
  Offset(SolidPtr solid, double amount) : solid_(std::move(solid)), amount_(amount) {}
  double value(const Eigen::Vector3d& p) const override { return solid_->value(p) + amount_; }
  Interval range(const IntervalBox& box) const override { return solid_->range(box) + amount_; }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    return solid_->superlevelBounds(detail::levelDown(level, amount_));
  }

 private:
  SolidPtr solid_;
  double amount_;
};

class Transformed final : public Solid {
 public:
  Transformed(SolidPtr solid, const Eigen::Affine3d& transform)
      : solid_(std::move(solid)), forward_(transform), inverse_(transform.inverse()) {}
  double value(const Eigen::Vector3d& p) const override { return solid_->value(inverse_ * p); }
  Interval range(const IntervalBox& box) const override {
    IntervalBox local;
    for (int i = 0; i < 3; ++i) {
      Interval sum = point(inverse_.translation()[i]);
      for (int j = 0; j < 3; ++j)
        sum += inverse_.linear()(i, j) * box.axis[j];
      local.axis[i] = sum;
    }
    return solid_->range(local);
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    // The solid is exactly f(M x + t) for the stored (rounded) inverse (M, t); its points are
    // x = M^-1 (y - t) for y in the child's box. With F ~ M^-1 (the forward map) and
    // R = I - M F (interval arithmetic, r = |R|_inf < 1/2): M^-1 = F (I - R)^-1, so
    // |M^-1 - F|_inf <= |F|_inf r / (1 - r). x lies in the interval image F (y - t), widened by
    // that bound times |y - t|_inf.
    const Eigen::AlignedBox3d local = solid_->superlevelBounds(level);
    if (local.isEmpty()) return emptyBox();
    if (!isFinite(local)) return infiniteBox();
    const Eigen::Matrix3d& f = forward_.linear();
    const Eigen::Matrix3d& m = inverse_.linear();
    const Eigen::Vector3d& t = inverse_.translation();
    double r = 0.0;
    double f_norm = 0.0;
    for (int i = 0; i < 3; ++i) {
      Interval row(0.0);
      double f_row = 0.0;
      for (int j = 0; j < 3; ++j) {
        Interval entry = point(i == j ? 1.0 : 0.0);
        for (int k = 0; k < 3; ++k)
          entry -= point(m(i, k)) * f(k, j);
        row += abs(entry);
        f_row = OutwardRounding::up(f_row + std::abs(f(i, j)));
      }
      r = std::max(r, row.upper());
      f_norm = std::max(f_norm, f_row);
    }
    if (!(r < 0.5)) return infiniteBox();
    IntervalBox shifted = IntervalBox::of(local);
    double reach = 0.0;
    for (int j = 0; j < 3; ++j) {
      shifted.axis[j] -= t[j];
      reach = std::max(reach, norm(shifted.axis[j]));
    }
    const double slack = (point(f_norm) * r / (1.0 - point(r)) * reach).upper();
    Eigen::AlignedBox3d box;
    for (int i = 0; i < 3; ++i) {
      Interval x(0.0);
      for (int j = 0; j < 3; ++j)
        x += f(i, j) * shifted.axis[j];
      box.min()[i] = OutwardRounding::down(x.lower() - slack);
      box.max()[i] = OutwardRounding::up(x.upper() + slack);
    }
    return box;
  }

 private:
  SolidPtr solid_;
  Eigen::Affine3d forward_;
  Eigen::Affine3d inverse_;
};

class Twisted final : public Solid {
 public:
  Twisted(SolidPtr solid, double rate) : solid_(std::move(solid)), rate_(rate) {}
  double value(const Eigen::Vector3d& p) const override {
    const double angle = rate_ * p.z();
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    return solid_->value({c * p.x() + s * p.y(), -s * p.x() + c * p.y(), p.z()});
  }
  Interval range(const IntervalBox& box) const override {
    const Interval angle = rate_ * box.axis[2];
    const Interval c = cos(angle);
    const Interval s = sin(angle);
    const Interval& x = box.axis[0];
    const Interval& y = box.axis[1];
    return solid_->range({{c * x + s * y, c * y - s * x, box.axis[2]}});
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    // Turning about z keeps each point's distance from the axis and its height.
    const Eigen::AlignedBox3d local = solid_->superlevelBounds(level);
    if (local.isEmpty() || !isFinite(local)) return local.isEmpty() ? emptyBox() : infiniteBox();
    const double x = std::max(std::abs(local.min().x()), std::abs(local.max().x()));
    const double y = std::max(std::abs(local.min().y()), std::abs(local.max().y()));
    const double reach = std::hypot(x, y);
    return detail::padded(Eigen::AlignedBox3d(Eigen::Vector3d(-reach, -reach, local.min().z()),
                                              Eigen::Vector3d(reach, reach, local.max().z())));
  }

 private:
  SolidPtr solid_;
  double rate_;
};

class Morphed final : public Solid {
 public:
  Morphed(SolidPtr a, SolidPtr b, double t) : a_(std::move(a)), b_(std::move(b)), t_(t) {}
  double value(const Eigen::Vector3d& p) const override {
    return (1.0 - t_) * a_->value(p) + t_ * b_->value(p);
  }
  Interval range(const IntervalBox& box) const override {
    return (1.0 - point(t_)) * a_->range(box) + t_ * b_->range(box);
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    // A convex combination is at most the larger of the two.
    return detail::unionOf(a_->superlevelBounds(level), b_->superlevelBounds(level));
  }

 private:
  SolidPtr a_;
  SolidPtr b_;
  double t_;
};

// ---- sweep and projection ------------------------------------------------------------------

// The running largest of the pieces' bounds, keeping a NaN (std::max would drop it).
void raiseTo(double& running, double value) {
  if (std::isnan(value) || std::isnan(running))
    running = std::numeric_limits<double>::quiet_NaN();
  else
    running = std::max(running, value);
}

// A NaN among the pieces' bounds says nothing: the whole line.
Interval guarded(double lower, double upper) {
  if (std::isnan(lower) || std::isnan(upper))
    return Interval(-std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity());
  return Interval(lower, std::max(lower, upper));
}

IntervalBox shiftedBy(const IntervalBox& box, const IntervalBox& shift) {
  return {{box.axis[0] - shift.axis[0], box.axis[1] - shift.axis[1], box.axis[2] - shift.axis[2]}};
}

class Swept final : public Solid {
 public:
  Swept(SolidPtr solid, std::vector<Eigen::Vector3d> path, int pieces)
      : solid_(std::move(solid)), path_(std::move(path)) {
    // Sample points and piece boxes in interval arithmetic, so that the pieces' boxes hold the
    // exact path and every sample box holds an exact path point.
    for (std::size_t i = 0; i + 1 < path_.size(); ++i) {
      const IntervalBox from = IntervalBox::ofPoint(path_[i]);
      const IntervalBox to = IntervalBox::ofPoint(path_[i + 1]);
      IntervalBox previous = from;
      if (i == 0) samples_.push_back(from);
      for (int k = 1; k <= pieces; ++k) {
        const Interval s = point(k) / point(pieces);
        IntervalBox next;
        for (int a = 0; a < 3; ++a)
          next.axis[a] = from.axis[a] + (to.axis[a] - from.axis[a]) * s;
        if (k == pieces) next = to;
        IntervalBox piece;
        for (int a = 0; a < 3; ++a)
          piece.axis[a] = hull(previous.axis[a], next.axis[a]);
        pieces_.push_back(piece);
        samples_.push_back(next);
        previous = next;
      }
    }
    for (const IntervalBox& sample : samples_) {
      points_.emplace_back(median(sample.axis[0]), median(sample.axis[1]), median(sample.axis[2]));
    }
  }
  double value(const Eigen::Vector3d& p) const override {
    double best = -std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& q : points_)
      best = std::max(best, solid_->value(p - q));
    return best;
  }
  Interval range(const IntervalBox& box) const override {
    // g >= f(x - q) at any path point q; g <= the largest bound over the pieces.
    double lower = -std::numeric_limits<double>::infinity();
    for (const IntervalBox& sample : samples_)
      raiseTo(lower, solid_->range(shiftedBy(box, sample)).lower());
    double upper = -std::numeric_limits<double>::infinity();
    for (const IntervalBox& piece : pieces_)
      raiseTo(upper, solid_->range(shiftedBy(box, piece)).upper());
    return guarded(lower, upper);
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    const Eigen::AlignedBox3d local = solid_->superlevelBounds(level);
    if (local.isEmpty()) return emptyBox();
    Eigen::AlignedBox3d path;
    for (const Eigen::Vector3d& p : path_)
      path.extend(p);
    return detail::padded(Eigen::AlignedBox3d(local.min() + path.min(), local.max() + path.max()));
  }

 private:
  SolidPtr solid_;
  std::vector<Eigen::Vector3d> path_;
  std::vector<IntervalBox> samples_;
  std::vector<IntervalBox> pieces_;
  std::vector<Eigen::Vector3d> points_;
};

class Projected final : public Solid {
 public:
  Projected(SolidPtr solid, int axis, int pieces) : solid_(std::move(solid)), axis_(axis) {
    const Eigen::AlignedBox3d extent = solid_->bounds();
    require(!extent.isEmpty(), "projected solid is empty");
    require(std::isfinite(extent.min()[axis]) && std::isfinite(extent.max()[axis]),
            "projected solid must be bounded along the projection axis");
    const double from = extent.min()[axis];
    const double to = extent.max()[axis];
    for (int k = 0; k <= pieces; ++k)
      cuts_.push_back(k == pieces ? to : from + (to - from) * k / pieces);
  }
  double value(const Eigen::Vector3d& p) const override {
    double best = -std::numeric_limits<double>::infinity();
    Eigen::Vector3d q = p;
    for (double s : cuts_) {
      q[axis_] = s;
      best = std::max(best, solid_->value(q));
    }
    return best;
  }
  Interval range(const IntervalBox& box) const override {
    // The cuts are doubles, so consecutive pieces cover the extent exactly.
    IntervalBox at = box;
    double lower = -std::numeric_limits<double>::infinity();
    for (double s : cuts_) {
      at.axis[axis_] = point(s);
      raiseTo(lower, solid_->range(at).lower());
    }
    double upper = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k + 1 < cuts_.size(); ++k) {
      at.axis[axis_] = Interval(cuts_[k], cuts_[k + 1]);
      raiseTo(upper, solid_->range(at).upper());
    }
    return guarded(lower, upper);
  }
  Eigen::AlignedBox3d superlevelBounds(double level) const override {
    Eigen::AlignedBox3d box = solid_->superlevelBounds(level);
    if (box.isEmpty()) return emptyBox();
    box.min()[axis_] = -std::numeric_limits<double>::infinity();
    box.max()[axis_] = std::numeric_limits<double>::infinity();
    return box;
  }

 private:
  SolidPtr solid_;
  int axis_;
  std::vector<double> cuts_;
};

}  // namespace

SolidPtr perturbed(SolidPtr solid, std::vector<Bump> bumps) {
  requireSolid(solid, "perturbation");
  for (const Bump& bump : bumps) {
    require(bump.centre.allFinite(), "bump centre must be finite");
    require(bump.radius > 0 && std::isfinite(bump.radius), "bump radius must be finite and > 0");
    require(std::isfinite(bump.amplitude), "bump amplitude must be finite");
  }
  return std::make_shared<Perturbed>(std::move(solid), std::move(bumps));
}

SolidPtr unionOf(std::vector<SolidPtr> operands, SetBlend blend) {
  return fold(SetKind::kUnion, std::move(operands), blend, "union");
}

SolidPtr intersectionOf(std::vector<SolidPtr> operands, SetBlend blend) {
  return fold(SetKind::kIntersection, std::move(operands), blend, "intersection");
}

SolidPtr differenceOf(SolidPtr a, SolidPtr b, SetBlend blend) {
  requireSolid(a, "difference");
  requireSolid(b, "difference");
  return std::make_shared<SetOperation>(SetKind::kIntersection, blend, std::move(a), std::move(b),
                                        true);
}

SolidPtr offset(SolidPtr solid, double amount) {
  requireSolid(solid, "offset");
  require(std::isfinite(amount), "offset must be finite");
  return std::make_shared<Offset>(std::move(solid), amount);
}

SolidPtr transformed(SolidPtr solid, const Eigen::Affine3d& transform) {
  requireSolid(solid, "transform");
  require(transform.matrix().allFinite(), "transform must be finite");
  const double det = transform.linear().determinant();
  require(std::abs(det) > 1e-12 * std::pow(transform.linear().cwiseAbs().maxCoeff(), 3),
          "transform must be invertible");
  return std::make_shared<Transformed>(std::move(solid), transform);
}

SolidPtr twisted(SolidPtr solid, double rate_radians_per_unit) {
  requireSolid(solid, "twist");
  require(std::isfinite(rate_radians_per_unit), "twist rate must be finite");
  return std::make_shared<Twisted>(std::move(solid), rate_radians_per_unit);
}

SolidPtr morphed(SolidPtr a, SolidPtr b, double t) {
  requireSolid(a, "morph");
  requireSolid(b, "morph");
  require(t >= 0 && t <= 1, "morph parameter must be in [0, 1]");
  return std::make_shared<Morphed>(std::move(a), std::move(b), t);
}

SolidPtr swept(SolidPtr solid, std::vector<Eigen::Vector3d> path, int pieces) {
  requireSolid(solid, "sweep");
  require(path.size() >= 2, "sweep path needs at least two points");
  for (const Eigen::Vector3d& p : path)
    require(p.allFinite(), "sweep path points must be finite");
  require(pieces >= 1 && pieces <= 4096, "sweep pieces must be in [1, 4096]");
  return std::make_shared<Swept>(std::move(solid), std::move(path), pieces);
}

SolidPtr projected(SolidPtr solid, int axis, int pieces) {
  requireSolid(solid, "projection");
  require(axis >= 0 && axis <= 2, "projection axis must be x, y or z");
  require(pieces >= 1 && pieces <= 4096, "projection pieces must be in [1, 4096]");
  return std::make_shared<Projected>(std::move(solid), axis, pieces);
}

}  // namespace collido::frep
