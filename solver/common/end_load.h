#pragma once
// Loads on the free end of an initially straight cantilever, nondimensional (length l = 1, EI = 1).
//
// The beam is clamped at the origin with its tangent along +x. A dead force (Fx, Fy) = F l^2/EI and
// an end moment mu = M l/EI (counter-clockwise positive) act at the tip. Howell's load ratio n
// gives the horizontal component as nP with n > 0 compressive (Howell Fig. 2.14, eq. 2.67), so Fy =
// alpha2 = P l^2/EI and Fx = -n * alpha2.
namespace flexure {

struct EndLoad {
  double Fx = 0.0;
  double Fy = 0.0;
  double mu = 0.0;

  // Howell's parameters: alpha2 = P l^2/EI (eq. 2.83), load_ratio_n = n (eq. 2.67).
  static EndLoad howell(double load_ratio_n, double alpha2, double mu = 0.0) {
    return EndLoad{-load_ratio_n * alpha2, alpha2, mu};
  }
  EndLoad scaled(double factor) const { return EndLoad{factor * Fx, factor * Fy, factor * mu}; }
};

// Tip of the deflected cantilever: a/l, b/l (Howell's a and b) and the tip angle theta0 in radians.
struct TipPose {
  double a_over_l = 1.0;
  double b_over_l = 0.0;
  double theta0 = 0.0;
};

// A force (Fx, Fy) and a counter-clockwise moment M in the root frame: what a support or the
// clamp exerts on a beam or chain (nondimensional where the problem is).
struct Reaction {
  double Fx = 0.0;
  double Fy = 0.0;
  double M = 0.0;
};

// One point of the deflected shape at arc length s (0 <= s <= 1).
struct ShapePoint {
  double s = 0.0;
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;
};

}  // namespace flexure
