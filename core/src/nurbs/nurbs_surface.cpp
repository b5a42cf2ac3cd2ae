// NURBS surfaces: validation, evaluation by the B-spline basis and its first derivatives, and
// Boehm knot insertion for splitting into sub-patches.
#include <collido/nurbs/nurbs_surface.h>

#include <algorithm>
#include <cmath>

namespace collido::nurbs {
namespace {

using Vec4 = Eigen::Vector4d;

// The knot at an int index (knot arithmetic is in ints; indices are never negative here).
double knotAt(const std::vector<double>& knots, int i) {
  return knots[static_cast<std::size_t>(i)];
}

// The knot span holding t: the index k with U[k] <= t < U[k + 1], and the last non-empty span
// at the domain's end.
int findSpan(int count, int degree, double t, const std::vector<double>& knots) {
  const int n = count - 1;
  if (t >= knotAt(knots, n + 1)) {
    int k = n;
    while (k > degree && knotAt(knots, k) == knotAt(knots, n + 1))
      --k;
    return k;
  }
  if (t <= knotAt(knots, degree)) {
    int k = degree;
    while (knotAt(knots, k + 1) <= t)
      ++k;
    return k;
  }
  const auto first = knots.begin() + degree;
  const auto last = knots.begin() + n + 2;
  return static_cast<int>(std::upper_bound(first, last, t) - knots.begin()) - 1;
}

// The degree-p basis functions N_{k-p..k} at t, and their derivatives.
void basis(int span, double t, int degree, const std::vector<double>& knots, double* values,
           double* derivatives) {
  double left[16];
  double right[16];
  double lower[16];  // the degree p - 1 functions N_{k-p+1..k}
  values[0] = 1.0;
  lower[0] = 1.0;
  for (int j = 1; j <= degree; ++j) {
    left[j] = t - knotAt(knots, span + 1 - j);
    right[j] = knotAt(knots, span + j) - t;
    if (j == degree) std::copy(values, values + degree, lower);
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double denominator = right[r + 1] + left[j - r];
      const double temp = denominator != 0.0 ? values[r] / denominator : 0.0;
      values[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    values[j] = saved;
  }
  const auto knot = [&](int i) { return knotAt(knots, i); };
  for (int r = 0; r <= degree; ++r) {
    double d = 0.0;
    if (r >= 1) {
      const double span_length = knot(span + r) - knot(span - degree + r);
      if (span_length > 0.0) d += lower[r - 1] / span_length;
    }
    if (r <= degree - 1) {
      const double span_length = knot(span + r + 1) - knot(span - degree + r + 1);
      if (span_length > 0.0) d -= lower[r] / span_length;
    }
    derivatives[r] = degree * d;
  }
}

int multiplicity(const std::vector<double>& knots, double t) {
  return static_cast<int>(std::count(knots.begin(), knots.end(), t));
}

// Inserts t once into the rows (u) or columns (v) of the net.
void insertOnce(NurbsSurface& s, Direction direction, double t) {
  const bool along_u = direction == Direction::kU;
  std::vector<double>& knots = along_u ? s.knots_u : s.knots_v;
  const int degree = along_u ? s.degree_u : s.degree_v;
  const int count = along_u ? s.count_u : s.count_v;
  const int other = along_u ? s.count_v : s.count_u;
  const int k = findSpan(count, degree, t, knots);
  const auto old_at = [&](int i, int j) -> const Vec4& {
    return along_u ? s.at(i, j) : s.at(j, i);
  };
  NurbsSurface out = s;
  (along_u ? out.count_u : out.count_v) = count + 1;
  out.control.assign((static_cast<std::size_t>(count) + 1) * static_cast<std::size_t>(other),
                     Vec4::Zero());
  const auto new_at = [&](int i, int j) -> Vec4& { return along_u ? out.at(i, j) : out.at(j, i); };
  for (int j = 0; j < other; ++j) {
    for (int i = 0; i <= count; ++i) {
      if (i <= k - degree) {
        new_at(i, j) = old_at(i, j);
      } else if (i >= k + 1) {
        new_at(i, j) = old_at(i - 1, j);
      } else {
        const double alpha =
            (t - knotAt(knots, i)) / (knotAt(knots, i + degree) - knotAt(knots, i));
        new_at(i, j) = alpha * old_at(i, j) + (1.0 - alpha) * old_at(i - 1, j);
      }
    }
  }
  std::vector<double>& new_knots = along_u ? out.knots_u : out.knots_v;
  new_knots.insert(new_knots.begin() + k + 1, t);
  s = std::move(out);
}

}  // namespace

Eigen::Vector3d NurbsSurface::point(int i, int j) const {
  const Vec4& p = at(i, j);
  return p.head<3>() / p.w();
}

Eigen::Matrix3Xd NurbsSurface::controlPoints() const {
  Eigen::Matrix3Xd points(3, static_cast<Eigen::Index>(control.size()));
  for (std::size_t k = 0; k < control.size(); ++k)
    points.col(static_cast<Eigen::Index>(k)) = control[k].head<3>() / control[k].w();
  return points;
}

NurbsSurface NurbsSurface::fromPoints(int degree_u, int degree_v, int count_u, int count_v,
                                      std::vector<double> knots_u, std::vector<double> knots_v,
                                      const std::vector<Eigen::Vector3d>& points,
                                      const std::vector<double>& weights) {
  NurbsSurface s;
  s.degree_u = degree_u;
  s.degree_v = degree_v;
  s.count_u = count_u;
  s.count_v = count_v;
  s.knots_u = std::move(knots_u);
  s.knots_v = std::move(knots_v);
  s.control.resize(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double w = k < weights.size() ? weights[k] : 1.0;
    s.control[k] << w * points[k], w;
  }
  return s;
}

Status validate(const NurbsSurface& s) {
  const auto bad = [](const std::string& text) {
    return Status(StatusCode::kInvalidArgument, text);
  };
  for (const auto& [name, degree, count, knots] :
       {std::tuple<const char*, int, int, const std::vector<double>*>{"u", s.degree_u, s.count_u,
                                                                      &s.knots_u},
        {"v", s.degree_v, s.count_v, &s.knots_v}}) {
    const std::string axis = name;
    if (degree < 1 || degree > 15) {
      return bad("degree_" + axis + " is " + std::to_string(degree) + ": must be 1 to 15");
    }
    if (count < degree + 1) {
      return bad("count_" + axis + " is " + std::to_string(count) + ": degree " +
                 std::to_string(degree) + " needs at least " + std::to_string(degree + 1) +
                 " control points");
    }
    if (knots->size() != static_cast<std::size_t>(count) + static_cast<std::size_t>(degree) + 1) {
      return bad("knots_" + axis + " has " + std::to_string(knots->size()) +
                 " values: count + degree + 1 = " + std::to_string(count + degree + 1) +
                 " expected");
    }
    for (std::size_t i = 0; i < knots->size(); ++i) {
      if (!std::isfinite((*knots)[i])) {
        return bad("knots_" + axis + "[" + std::to_string(i) + "] is not a finite number");
      }
      if (i > 0 && (*knots)[i] < (*knots)[i - 1]) {
        return bad("knots_" + axis + ": not non-decreasing at index " + std::to_string(i));
      }
    }
    const auto p = static_cast<std::size_t>(degree);
    for (std::size_t i = 1; i <= p; ++i) {
      if ((*knots)[i] != (*knots)[0] || (*knots)[knots->size() - 1 - i] != knots->back()) {
        return bad("knots_" + axis + ": not clamped (the first and last " + std::to_string(p + 1) +
                   " knots must be equal)");
      }
    }
    if (!((*knots)[p] < knots->back())) return bad("knots_" + axis + ": empty domain");
    for (std::size_t i = p + 1; i + p + 1 < knots->size(); ++i) {
      if (multiplicity(*knots, (*knots)[i]) > degree) {
        return bad("knots_" + axis + ": interior knot " + std::to_string((*knots)[i]) +
                   " repeated more than the degree");
      }
    }
  }
  if (s.control.size() !=
      static_cast<std::size_t>(s.count_u) * static_cast<std::size_t>(s.count_v)) {
    return bad("control net has " + std::to_string(s.control.size()) + " points, " +
               std::to_string(s.count_u) + " x " + std::to_string(s.count_v) + " expected");
  }
  for (int i = 0; i < s.count_u; ++i) {
    for (int j = 0; j < s.count_v; ++j) {
      const Vec4& p = s.at(i, j);
      const std::string where = "(" + std::to_string(i) + ", " + std::to_string(j) + ")";
      if (!(std::isfinite(p.w()) && p.w() > 0.0)) {
        return bad("weight of control point " + where + " is " + std::to_string(p.w()) +
                   ": must be > 0 and finite");
      }
      if (!p.allFinite()) return bad("control point " + where + " has a non-finite coordinate");
    }
  }
  return {};
}

SurfacePoint evaluateWithDerivatives(const NurbsSurface& s, double u, double v) {
  u = std::clamp(u, s.uMin(), s.uMax());
  v = std::clamp(v, s.vMin(), s.vMax());
  const int su = findSpan(s.count_u, s.degree_u, u, s.knots_u);
  const int sv = findSpan(s.count_v, s.degree_v, v, s.knots_v);
  double nu[16];
  double dnu[16];
  double nv[16];
  double dnv[16];
  basis(su, u, s.degree_u, s.knots_u, nu, dnu);
  basis(sv, v, s.degree_v, s.knots_v, nv, dnv);
  Vec4 w = Vec4::Zero();
  Vec4 wu = Vec4::Zero();
  Vec4 wv = Vec4::Zero();
  for (int a = 0; a <= s.degree_u; ++a) {
    Vec4 row = Vec4::Zero();
    Vec4 row_v = Vec4::Zero();
    for (int b = 0; b <= s.degree_v; ++b) {
      const Vec4& p = s.at(su - s.degree_u + a, sv - s.degree_v + b);
      row += nv[b] * p;
      row_v += dnv[b] * p;
    }
    w += nu[a] * row;
    wu += dnu[a] * row;
    wv += nu[a] * row_v;
  }
  SurfacePoint out;
  out.point = w.head<3>() / w.w();
  out.du = (wu.head<3>() - wu.w() * out.point) / w.w();
  out.dv = (wv.head<3>() - wv.w() * out.point) / w.w();
  return out;
}

Eigen::Vector3d evaluate(const NurbsSurface& s, double u, double v) {
  return evaluateWithDerivatives(s, u, v).point;
}

NurbsSurface insertKnot(const NurbsSurface& surface, Direction direction, double t, int times) {
  NurbsSurface s = surface;
  for (int k = 0; k < times; ++k)
    insertOnce(s, direction, t);
  return s;
}

std::array<NurbsSurface, 2> splitAt(const NurbsSurface& surface, Direction direction, double t) {
  const bool along_u = direction == Direction::kU;
  const int degree = along_u ? surface.degree_u : surface.degree_v;
  const int existing = multiplicity(along_u ? surface.knots_u : surface.knots_v, t);
  const NurbsSurface full = insertKnot(surface, direction, t, std::max(0, degree - existing));
  const std::vector<double>& knots = along_u ? full.knots_u : full.knots_v;
  const int count = along_u ? full.count_u : full.count_v;
  const int other = along_u ? full.count_v : full.count_u;
  const int a = static_cast<int>(std::find(knots.begin(), knots.end(), t) - knots.begin());
  std::array<NurbsSurface, 2> pieces{full, full};
  // Left: knots [0, a + degree) then t; control rows [0, a). Right: t then knots [a, end);
  // control rows [a - 1, count). Row a - 1 is the point on the cut, shared.
  std::vector<double> left_knots(knots.begin(), knots.begin() + a + degree);
  left_knots.push_back(t);
  std::vector<double> right_knots{t};
  right_knots.insert(right_knots.end(), knots.begin() + a, knots.end());
  const int left_count = a;
  const int right_count = count - a + 1;
  for (int side = 0; side < 2; ++side) {
    NurbsSurface& piece = pieces[static_cast<std::size_t>(side)];
    const int rows = side == 0 ? left_count : right_count;
    const int first = side == 0 ? 0 : a - 1;
    (along_u ? piece.knots_u : piece.knots_v) = side == 0 ? left_knots : right_knots;
    (along_u ? piece.count_u : piece.count_v) = rows;
    piece.control.assign(static_cast<std::size_t>(rows) * static_cast<std::size_t>(other),
                         Vec4::Zero());
    for (int i = 0; i < rows; ++i) {
      for (int j = 0; j < other; ++j) {
        if (along_u) {
          piece.at(i, j) = full.at(first + i, j);
        } else {
          piece.at(j, i) = full.at(j, first + i);
        }
      }
    }
  }
  return pieces;
}

std::array<NurbsSurface, 4> splitInFour(const NurbsSurface& surface) {
  const double mid_u = 0.5 * (surface.uMin() + surface.uMax());
  const double mid_v = 0.5 * (surface.vMin() + surface.vMax());
  const std::array<NurbsSurface, 2> halves = splitAt(surface, Direction::kU, mid_u);
  const std::array<NurbsSurface, 2> low = splitAt(halves[0], Direction::kV, mid_v);
  const std::array<NurbsSurface, 2> high = splitAt(halves[1], Direction::kV, mid_v);
  return {low[0], low[1], high[0], high[1]};
}

SurfaceView viewOf(const NurbsSurface& surface) {
  const auto points = static_cast<Eigen::Index>(surface.control.size());
  return SurfaceView{
      surface.degree_u,
      surface.degree_v,
      surface.count_u,
      surface.count_v,
      Eigen::Map<const Eigen::VectorXd>(surface.knots_u.data(),
                                        static_cast<Eigen::Index>(surface.knots_u.size())),
      Eigen::Map<const Eigen::VectorXd>(surface.knots_v.data(),
                                        static_cast<Eigen::Index>(surface.knots_v.size())),
      Eigen::Map<const Eigen::Matrix4Xd>(
          surface.control.empty() ? nullptr : surface.control.front().data(), 4, points)};
}

NurbsSurface fromView(const SurfaceView& view) {
  NurbsSurface s;
  s.degree_u = view.degree_u;
  s.degree_v = view.degree_v;
  s.count_u = view.count_u;
  s.count_v = view.count_v;
  s.knots_u.assign(view.knots_u.data(), view.knots_u.data() + view.knots_u.size());
  s.knots_v.assign(view.knots_v.data(), view.knots_v.data() + view.knots_v.size());
  s.control.resize(static_cast<std::size_t>(view.control.cols()));
  for (Eigen::Index k = 0; k < view.control.cols(); ++k)
    s.control[static_cast<std::size_t>(k)] = view.control.col(k);
  return s;
}

NurbsSurface transformed(const NurbsSurface& surface, const Pose& pose) {
  NurbsSurface moved = surface;
  for (Eigen::Vector4d& c : moved.control) {
    c.head<3>() = pose.linear() * c.head<3>() + c.w() * pose.translation();
  }
  return moved;
}

}  // namespace collido::nurbs
