#pragma once
// The pseudo-rigid-body model of a GeneralMechanism assembled from the PRBM elements (Howell
// ch. 5-6, 11; docs/mechanisms.md "General mechanisms"): generalised coordinates, the loop-closure
// constraints, the potential energy and the input coordinate, with their derivatives.
//
// Coordinates. Every moving body -- the described ones, then one hidden PRB link for each
// fixed-pinned or fixed-guided flexure -- has three: the displacement (x, y) of its reference
// point (the centroid of its points) and its rotation phi, all zero in the described
// configuration. A point r of a body is at c0 + (x, y) + R(phi)(r - c0).
//
// Constraints g(q) = 0: a pin (two rows: the points coincide), a slider (the point's distance from
// the line, and the relative angle), a weld (a pin and the relative angle), and the pins each
// flexure's PRB model adds (elements/: the small-length pivot's mid-length pivot, eq. 5.6; the
// fixed-pinned segment's pivot (1 - gamma) l from the clamp and its pinned far end, eq. 5.72; the
// fixed-guided segment's two pivots, eq. 5.105).
//
// Energy V(q) = sum K_i psi_i^2/2 over the torsion springs (each flexure's PRB springs,
// K = K_coefficient EI/l, and the described torsion springs; psi = phi_b - phi_a - rest, Howell
// eq. 11.6) + sum k (|p_b - p_a| - L0)^2/2 over the linear springs (eq. 11.2) - the work of the
// dead loads.
//
// Everything here is nondimensional: lengths divided by the mechanism's size L, energies by the
// largest spring's stiffness K (N m), so that the Newton systems are well scaled; the *_si
// functions convert. The Hessian of the Lagrangian is the central difference of its analytic
// gradient (step 1e-6 in the scaled coordinates; error about 1e-10 of the stiffness, far below the
// critical tolerance 1e-6 of the stability verdict).
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "flexure/mechanisms/general/general_mechanism.h"

namespace flexure::mechanism::general {

class PrbmAssembly {
 public:
  // Validates the description (GeneralMechanism::validate) and assembles its PRBM. With
  // `assemble_flexures` false the flexures add nothing (no PRB pins, springs or links): the exact
  // model (general_analysis.h) adds them as elastica between their bodies instead.
  explicit PrbmAssembly(const GeneralMechanism& mechanism, bool assemble_flexures = true);

  int coordinate_count() const { return 3 * static_cast<int>(bodies_.size()); }
  int constraint_count() const { return constraint_rows_; }
  int described_body_count() const { return described_bodies_; }
  // Names of the moving bodies in coordinate order ("flexure 'f1' PRB link" for hidden ones).
  std::vector<std::string> body_names() const;

  Eigen::VectorXd constraints(const Eigen::VectorXd& q) const;
  Eigen::MatrixXd constraint_jacobian(const Eigen::VectorXd& q) const;
  // Names of the item behind each constraint row (for messages).
  const std::vector<std::string>& constraint_items() const { return constraint_items_; }

  double energy(const Eigen::VectorXd& q) const;
  Eigen::VectorXd energy_gradient(const Eigen::VectorXd& q) const;
  // The springs' stiffness without their preload, sum k grad psi grad psi^T: the B that the
  // stability margin measures against (docs/stability.md "Mechanisms").
  Eigen::MatrixXd unloaded_stiffness(const Eigen::VectorXd& q) const;
  // The spring energy alone (no dead loads), and the stored energy of each flexure.
  double spring_energy(const Eigen::VectorXd& q) const;

  double input(const Eigen::VectorXd& q) const;
  Eigen::VectorXd input_gradient(const Eigen::VectorXd& q) const;

  // grad V - lambda grad c - J_g^T mu, and its Jacobian in q (central differences).
  Eigen::VectorXd lagrangian_gradient(const Eigen::VectorXd& q,
                                      const Eigen::VectorXd& mu,
                                      double lambda) const;
  Eigen::MatrixXd lagrangian_hessian(const Eigen::VectorXd& q,
                                     const Eigen::VectorXd& mu,
                                     double lambda) const;

  // Position (SI, m) of a named point of a described body at coordinates q.
  Vec2 point_position_si(const Eigen::VectorXd& q, const PointRef& ref) const;
  // The same in scaled units, the rotation of a body (0 for the ground), and the generalised
  // force of a force (scaled) at a body point and a moment on its body: F . dp/dq + M dphi/dq,
  // added to `generalized`.
  Eigen::Vector2d point_scaled(const Eigen::VectorXd& q, const PointRef& ref) const;
  double body_rotation(const Eigen::VectorXd& q, const std::string& body) const;
  void add_wrench(const Eigen::VectorXd& q,
                  const PointRef& ref,
                  const Eigen::Vector2d& force,
                  double moment,
                  Eigen::VectorXd& generalized) const;

  // Reactions (docs/mechanisms.md "Reactions, stresses and shapes"), SI, from the multipliers mu
  // of the constraints (the generalised force J_g^T mu acts on the bodies): (fx, fy, moment).
  // Joint j of the description: the load body a puts on body b through it, the force at the
  // joint's point of body b and the moment (a slider's or weld's; 0 for a pin) about it.
  Eigen::Vector3d joint_reaction_si(const Eigen::VectorXd& q,
                                    const Eigen::VectorXd& mu,
                                    int j) const;
  // Flexure i's PRB element (assembled flexures only): the load it puts on body a (end 0) or body
  // b (end 1), the force and the moment about the flexure's end point there.
  Eigen::Vector3d flexure_end_load_si(const Eigen::VectorXd& q,
                                      const Eigen::VectorXd& mu,
                                      int i,
                                      int end) const;
  // Flexure i's PRB linkage from end a through its pivots to end b (SI, m); its end tangents:
  // the rest direction turned with body a at end a, and with body b at end b (clamped) or along
  // the last PRB link (pinned).
  std::vector<Vec2> flexure_prb_points_si(const Eigen::VectorXd& q, int i) const;
  double flexure_end_angle(const Eigen::VectorXd& q, int i, int end) const;
  // The load the ground puts on the mechanism through the joints, the assembled flexures' PRB
  // elements and the springs attached to it: force and moment about the global origin (SI).
  Eigen::Vector3d ground_reaction_si(const Eigen::VectorXd& q, const Eigen::VectorXd& mu) const;

  // Scales: lengths (m), energies (J = N m).
  double length_scale() const { return length_scale_; }
  double energy_scale() const { return energy_scale_; }
  bool input_is_angle() const { return input_.coordinate == InputCoordinate::kAngle; }
  // The input coordinate, its conjugate load and the energy in SI, and back.
  double input_si(double s) const { return input_is_angle() ? s : s * length_scale_; }
  double input_scaled(double si) const { return input_is_angle() ? si : si / length_scale_; }
  double load_si(double lambda) const {
    return input_is_angle() ? lambda * energy_scale_ : lambda * energy_scale_ / length_scale_;
  }
  double load_scaled(double si) const {
    return input_is_angle() ? si / energy_scale_ : si * length_scale_ / energy_scale_;
  }
  double energy_si(double v) const { return v * energy_scale_; }
  const Input& input_description() const { return input_; }

 private:
  // A row of a matrix or a row vector (a row of a column-major matrix has an inner stride).
  using RowRef = Eigen::Ref<Eigen::RowVectorXd, 0, Eigen::InnerStride<>>;
  struct Pt {
    int body = -1;  // index into bodies_, -1 for the ground
    Eigen::Vector2d c0;
    Eigen::Vector2d r;  // point - c0, scaled
  };
  struct Frame {
    std::string name;
    Eigen::Vector2d c0;
  };
  struct Constraint {
    JointKind kind = JointKind::kPin;
    Pt a;
    Pt b;
    double axis_angle = 0.0;
  };
  struct Torsion {
    int a = -1;
    int b = -1;
    double k = 0.0;
    double rest = 0.0;
  };
  struct Linear {
    Pt a;
    Pt b;
    double k = 0.0;
    double rest = 0.0;
  };
  struct Load {
    Pt at;
    Eigen::Vector2d force;
    double moment = 0.0;
  };

  int body_index(const std::string& name) const;  // -1 for the ground
  Pt make_point(int body, const Eigen::Vector2d& position) const;
  Eigen::Vector2d position(const Eigen::VectorXd& q, const Pt& p) const;
  double phi(const Eigen::VectorXd& q, int body) const;
  // Adds d(position)/dq (row k of the 2 x N Jacobian) times `weight` into `row`.
  void add_position_gradient(const Eigen::VectorXd& q,
                             const Pt& p,
                             const Eigen::Vector2d& weight,
                             RowRef row) const;
  void add_phi_gradient(int body, double weight, RowRef row) const;

  // The wrench (force at the point, moment) of constraint c's rows starting at `row` on `body`,
  // scaled, as (fx, fy, moment about the global origin).
  Eigen::Vector3d constraint_wrench(
      const Eigen::VectorXd& q, const Eigen::VectorXd& mu, std::size_t c, int row, int body) const;
  // The torque of torsion spring t on `body`, scaled.
  double torsion_moment(const Eigen::VectorXd& q, std::size_t t, int body) const;
  // Per flexure (assembled): its constraints [first, first + count), their first row, and its
  // torsion springs [first, first + count).
  struct FlexureItems {
    std::size_t constraint = 0, constraints = 0;
    int row = 0;
    std::size_t torsion = 0, torsions = 0;
    int a = -1, b = -1;  // body indices of its ends
    Pt end_a, end_b;
    double rest_a = 0.0, rest_b = 0.0;  // rest tangents' angles at end a and end b, rad
    bool pinned = false;
  };
  std::vector<FlexureItems> flexure_items_;
  std::vector<int> constraint_first_row_;

  GeneralMechanism mechanism_;
  double length_scale_ = 1.0;
  double energy_scale_ = 1.0;
  std::vector<Frame> bodies_;
  int described_bodies_ = 0;
  std::vector<Constraint> constraints_;
  std::vector<std::string> constraint_items_;
  int constraint_rows_ = 0;
  std::vector<Torsion> torsions_;
  std::vector<Linear> linears_;
  std::vector<Load> loads_;
  Input input_;
  Pt input_point_;
  double input_angle0_ = 0.0;
};

}  // namespace flexure::mechanism::general
