#pragma once
// The parameter set that describes one closed-form elastica; separated from the solver header so
// that the closed-form layer does not depend on the solver.
#include "flexure/solver/common/end_load.h"

namespace flexure {

enum class ElasticaFamily {
  kStraight,         // no transverse load and no moment: the beam stays straight
  kCircularArc,      // no force: a circular arc of curvature mu (Howell eqs. 2.53-2.64)
  kInflectional,     // family A, -F < H < F: curvature may change sign
  kNonInflectional,  // family B, H > F: curvature keeps its sign (needs mu != 0)
};
const char* to_string(ElasticaFamily family);

// Everything needed to evaluate the closed-form shape at any arc length. Filled by the solver.
struct ElasticaParameters {
  ElasticaFamily family = ElasticaFamily::kStraight;
  double force = 0.0;        // F = |(Fx, Fy)| l^2/EI (after mirroring so that Fy >= 0)
  double psi = 0.0;          // force angle in [0, pi] (after mirroring)
  bool mirrored = false;     // the problem was mirrored about the x axis because Fy < 0
  double mu = 0.0;           // end moment (after mirroring)
  double chi_tip = 0.0;      // pendulum angle at the tip, chi = theta - psi + pi (after mirroring)
  double modulus2 = 0.0;     // k^2 (family A) or m (family B)
  double complement2 = 1.0;  // 1 - modulus2, kept separately for accuracy near the separatrix
  double u_root = 0.0;       // elliptic argument at the clamp (u in family A, v in family B)
  double u_tip = 0.0;        // elliptic argument at the tip
  int winding = 0;           // family A: chi oscillates about 2 pi winding; family B: chi =
                             // 2 pi winding + 2 am(v), whole half-turns kept out of v
};

}  // namespace flexure
