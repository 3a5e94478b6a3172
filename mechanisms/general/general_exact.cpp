#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "flexure/beam/physical_beam.h"
#include "flexure/elements/cbcm_march.h"
#include "flexure/elements/ladder_models.h"
#include "flexure/mechanisms/general/arclength_path.h"
#include "flexure/mechanisms/general/exact_stability.h"
#include "flexure/mechanisms/general/flexure_stress.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/mechanisms/general/prbm_assembly.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/elastica_integrator.h"

namespace flexure::mechanism::general {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// Shape samples of each flexure for its strain energy at a recorded point (trapezoidal rule on
// m^2/(2 EI): relative error about 1e-5).
constexpr int kEnergySamples = 257;
// Forward-difference step of the Jacobian, scaled coordinates (lengths / size, rad).
constexpr double kJacobianStep = 1e-7;
// Central-difference step of the linearised Jacobian (the flexures' tips linear in their loads,
// from the integrator's sensitivities: no integration noise; error about h^2 = 1e-12).
constexpr double kLinearisedStep = 1e-6;

std::string fmt(double v) {
  std::ostringstream out;
  out.precision(6);
  out << v;
  return out.str();
}

// One flexure as an elastica between its bodies, in scaled units (lengths / L, loads by the
// assembly's energy scale K: forces F L/K, moments M/K, EI/(K L)).
struct FlexureBeam {
  const Flexure* flexure = nullptr;
  SegmentChain chain;   // one flexible segment (scaled), for the integrator
  double length = 0.0;  // scaled
  double EI = 0.0;      // scaled
  double EA = std::numeric_limits<double>::infinity();  // scaled; infinite: inextensible
  double direction = 0.0;  // rest angle of the flexure from a to b, rad
  bool pinned_tip = false;
  double rest_turn = 0.0;  // the rest tangent's turn from end a to end b (kappa0 l), rad
  // At kEnergySamples equal arc lengths: EI (scaled) and the section (m), for a taper.
  std::vector<double> sample_EI, sample_width, sample_thickness;
  // kExact: an elastica with unknowns w = its root loads (m0, Nx, Ny). kCbcm (mixed): the
  // chained BCM marched from the same root loads (cbcm_march.h): a flexure whose tip under dead
  // loads would snap (the inclined bistable beam) stays regular, as the exact one does. Any other
  // model (mixed): a cantilever under its tip loads, unknowns w = (M_tip, Nx, Ny)
  // (general_mechanism.h).
  FlexureModel model = FlexureModel::kExact;
  int elements = 6;
  // Unknowns w are the root loads (the exact elastica and the marched CBCM).
  bool root_loads() const { return model == FlexureModel::kExact || model == FlexureModel::kCbcm; }
};

// The tip state of a beam integrated from its root loads: x, y, theta, m in the root frame.
struct BeamTip {
  double x = 0.0, y = 0.0, theta = 0.0, m = 0.0;
};

// An exact flexure's tip linearised in its root loads at w0 (the integrator's sensitivities).
struct TipLinearisation {
  Eigen::Vector3d w0;
  Eigen::Vector4d tip0;
  Eigen::Matrix<double, 4, 3> S;
  BeamTip at(const Eigen::Vector3d& w) const {
    const Eigen::Vector4d t = tip0 + S * (w - w0);
    return {t[0], t[1], t[2], t[3]};
  }
};

// The verdicts of one equilibrium (exact_stability.h).
struct PointVerdicts {
  Stability displacement_control;
  Stability force_control;
};

// Mixed formulation: the unknowns are the bodies' coordinates q, the joints' multipliers mu, the
// input load lambda and, per flexure, its root loads w = (m0, Nx, Ny) in its root frame (N the
// constant internal force = the load body b applies to the tip). Each residual integrates every
// flexure once from its root loads (an initial-value problem, elastica_integrator.h); the tip
// conditions are equations. Unlike prescribing the tip and solving for the loads, this stays
// regular at a straight flexure, whose axial force is then a multiplier of its inextensibility.
class ExactSystem {
 public:
  // `models` (one per flexure; empty: every one exact) and `elements` (cbcm) from the mixed model.
  ExactSystem(const GeneralMechanism& m,
              const PrbmAssembly& a,
              const std::vector<FlexureModel>& models = {},
              const std::vector<int>& elements = {})
      : a_(a),
        N_(a.coordinate_count()),
        m_(a.constraint_count()),
        integrator_(ElasticaIntegrator::Options{}),
        report_integrator_(ElasticaIntegrator::Options{}),
        sensitivity_integrator_(ElasticaIntegrator::Options{}),
        shape_integrator_(ElasticaIntegrator::Options{}) {
    const double L = a.length_scale();
    for (const Flexure& f : m.flexures) {
      FlexureBeam b;
      b.flexure = &f;
      const Vec2 pa = m.point(f.a);
      const Vec2 pb = m.point(f.b);
      const double chord = std::hypot(pb.x - pa.x, pb.y - pa.y);
      const double length_si = f.arc_length(chord);
      b.length = length_si / L;
      b.EI = f.flexural_rigidity() / (a.energy_scale() * L);
      // The root frame: x along the rest tangent at end a (the chord turned back by half the
      // arc's turn for a curved flexure), in which the integrator starts at theta = 0.
      b.direction = std::atan2(pb.y - pa.y, pb.x - pa.x) + f.end_angle_from_chord(chord, 0);
      b.rest_turn = f.curvature * length_si;
      b.pinned_tip = f.prbm == PrbmKind::kFixedPinned;
      // A taper as the physical beam's (beam/physical_beam.h): EI(s) at kTaperStations stations
      // (scaled), and the section at the samples of the energy and the stresses.
      PhysicalCantilever section;
      section.length = length_si;
      section.material.E = f.material.E;
      section.section = f.section();
      if (f.width_tip > 0.0) section.width_tip = f.width_tip;
      if (f.thickness_tip > 0.0) section.thickness_tip = f.thickness_tip;
      std::vector<double> profile;
      if (f.tapered()) {
        const int n = PhysicalCantilever::kTaperStations;
        for (int k = 0; k < n; ++k) {
          profile.push_back(f.material.E * section.second_moment_at(length_si * k / (n - 1)) /
                            (a.energy_scale() * L));
        }
      }
      for (int k = 0; k < kEnergySamples; ++k) {
        const double s_si = length_si * k / (kEnergySamples - 1);
        // (A uniform flexure keeps b.EI itself: its energy is the same number as before.)
        if (f.tapered()) {
          b.sample_EI.push_back(f.material.E * section.second_moment_at(s_si) /
                                (a.energy_scale() * L));
        }
        b.sample_width.push_back(*section.width_at(s_si));
        b.sample_thickness.push_back(*section.thickness_at(s_si));
      }
      b.chain.segments.push_back(FlexibleSegment{b.length, b.EI, profile, f.curvature * L});
      if (f.extensible) {
        // EA scaled as a force (F L/K): the strain N/EA is the same in both units.
        b.EA = f.axial_rigidity() * L / a.energy_scale();
        std::get<FlexibleSegment>(b.chain.segments.back()).EA = b.EA;
      }
      if (!models.empty()) {
        b.model = models[beams_.size()];
        b.elements = elements[beams_.size()];
      }
      beams_.push_back(b);
    }
  }

  int flexure_offset() const { return N_ + m_ + 1; }
  int size() const { return N_ + m_ + 1 + 3 * static_cast<int>(beams_.size()); }

  // Integrates beam b from root loads w; `shape` (optional) gets the pose at `samples` points.
  bool integrate(const FlexureBeam& b,
                 const Eigen::Vector3d& w,
                 BeamTip& tip,
                 std::vector<ShapePoint>* shape = nullptr,
                 int samples = 0,
                 ElasticaIntegrator* with = nullptr) {
    ChainForces forces;
    forces.m0 = w[0];
    forces.N = {Eigen::Vector2d(w[1], w[2])};
    forces.moment_drop = {0.0, 0.0};
    const std::vector<IntegrationPiece> pieces{IntegrationPiece{0, 0.0, b.length, 0.0, false}};
    std::vector<double> stations;
    for (int i = 0; i < samples; ++i) {
      stations.push_back(b.length * i / (samples - 1));
    }
    TipState end;
    std::string error;
    const Eigen::Matrix<double, 4, Eigen::Dynamic> no_sensitivity(4, 0);
    if (!(with != nullptr ? *with : integrator_)
             .integrate(b.chain,
                        pieces,
                        forces,
                        {},
                        Eigen::Vector4d(0, 0, 0, w[0]),
                        no_sensitivity,
                        end,
                        error,
                        shape != nullptr ? &stations : nullptr,
                        shape)) {
      return false;
    }
    tip = {end.x, end.y, end.theta, end.m};
    return true;
  }

  // A model flexure's tip under its tip loads w = (M_tip, Nx, Ny) (scaled): the tip state in the
  // root frame (scaled), its tip moment, and the nondimensional loads and tip.
  bool model_state(const FlexureBeam& b,
                   const Eigen::Vector3d& w,
                   BeamTip& tip,
                   FlexureTipLoad* load_out = nullptr,
                   FlexureTip* tip_out = nullptr) const {
    const double l2 = b.length * b.length / b.EI;
    const FlexureTipLoad load{w[1] * l2, w[2] * l2, w[0] * b.length / b.EI};
    FlexureTip t;
    if (!model_tip(b.model, b.flexure->prbm, b.elements, load, t)) {
      return false;
    }
    tip = {t.x * b.length, t.y * b.length, t.theta, w[0]};
    if (load_out != nullptr) *load_out = load;
    if (tip_out != nullptr) *tip_out = t;
    return true;
  }

  // A CBCM flexure's tip (scaled, root frame; tip.m the bending moment there) marched from its
  // root loads w = (m0, Nx, Ny) (scaled); `march` (optional) keeps the nodes (per length).
  static bool cbcm_state(const FlexureBeam& b,
                         const Eigen::Vector3d& w,
                         BeamTip& tip,
                         CbcmMarchResult* march = nullptr) {
    const double l = b.length, EI = b.EI;
    const double inverse_d = std::isfinite(b.EA) ? EI / (b.EA * l * l) : 0.0;
    CbcmMarchResult r;
    if (!cbcm_march(b.elements,
                    inverse_d,
                    w[0] * l / EI,
                    w[1] * l * l / EI,
                    w[2] * l * l / EI,
                    r,
                    march != nullptr)) {
      return false;
    }
    tip = {r.x * l, r.y * l, r.theta, r.m * EI / l};
    if (march != nullptr) *march = std::move(r);
    return true;
  }

  // The nondimensional tip loads and tip of flexure i at z (any model); false if not computable.
  bool flexure_state(const VectorXd& z, std::size_t i, FlexureTipLoad& load, FlexureTip& t) {
    const FlexureBeam& b = beams_[i];
    const Eigen::Vector3d w = z.segment<3>(flexure_offset() + 3 * static_cast<int>(i));
    BeamTip tip;
    if (!b.root_loads()) {
      return model_state(b, w, tip, &load, &t);
    }
    if (b.model == FlexureModel::kCbcm ? !cbcm_state(b, w, tip)
                                       : !integrate(b, w, tip, nullptr, 0, &report_integrator_)) {
      return false;
    }
    const double l2 = b.length * b.length / b.EI;
    load = {w[1] * l2, w[2] * l2, tip.m * b.length / b.EI};
    t = {tip.x / b.length, tip.y / b.length, tip.theta};
    return true;
  }

  std::size_t flexure_count() const { return beams_.size(); }

  // Residual at z = (q, mu, lambda, w...) and input s; false when an integration fails.
  bool residual(const VectorXd& z, double s, VectorXd& F) {
    const VectorXd q = z.head(N_);
    F.resize(size());
    VectorXd Q = VectorXd::Zero(N_);
    for (std::size_t i = 0; i < beams_.size(); ++i) {
      const FlexureBeam& b = beams_[i];
      const Flexure& f = *b.flexure;
      const int o = flexure_offset() + 3 * static_cast<int>(i);
      const Eigen::Vector3d w = z.segment<3>(o);
      BeamTip tip;
      double m0 = w[0];
      if (b.model == FlexureModel::kCbcm) {
        if (!cbcm_state(b, w, tip)) {
          return false;
        }
      } else if (b.model != FlexureModel::kExact) {
        if (!model_state(b, w, tip)) {
          return false;
        }
        // m(s) = m0 + Nx y(s) - Ny x(s): the root moment of the tip loads.
        m0 = w[0] - w[1] * tip.y + w[2] * tip.x;
      } else if (!linear_.empty()) {
        tip = linear_[i].at(w);
      } else if (!integrate(b, w, tip)) {
        return false;
      }
      const double beta = b.direction + a_.body_rotation(q, f.a.body);
      const double c = std::cos(beta), sn = std::sin(beta);
      const Eigen::Vector2d N(c * w[1] - sn * w[2], sn * w[1] + c * w[2]);  // global
      // The beam pushes its root body with +N, +m0 and its tip body with -N, -m(tip).
      a_.add_wrench(q, f.a, N, m0, Q);
      a_.add_wrench(q, f.b, -N, -tip.m, Q);
      const Eigen::Vector2d d = a_.point_scaled(q, f.b) - a_.point_scaled(q, f.a);
      F[o] = tip.x - (c * d.x() + sn * d.y());
      F[o + 1] = tip.y - (-sn * d.x() + c * d.y());
      F[o + 2] = b.pinned_tip ? tip.m  // a model flexure's tip.m is its unknown M_tip
                              : tip.theta - b.rest_turn -
                                    (a_.body_rotation(q, f.b.body) - a_.body_rotation(q, f.a.body));
    }
    F.head(N_) = a_.lagrangian_gradient(q, z.segment(N_, m_), z[N_ + m_]) - Q;
    F.segment(N_, m_) = a_.constraints(q);
    F[N_ + m_] = a_.input(q) - s;
    return F.allFinite();
  }

  // Damped Newton at input s from z (updated), Jacobian by forward differences.
  bool newton(VectorXd& z, double s, double tolerance, int max_iterations, int* iterations) {
    VectorXd F;
    if (!residual(z, s, F)) {
      return false;
    }
    for (int it = 0; it <= max_iterations; ++it) {
      const double r = F.lpNorm<Eigen::Infinity>();
      if (r < tolerance) {
        residual_ = std::max(residual_, r);
        return true;
      }
      if (it == max_iterations) {
        break;
      }
      ++*iterations;
      MatrixXd J(size(), size());
      for (int j = 0; j < size(); ++j) {
        VectorXd zp = z;
        const double h = kJacobianStep * std::max(1.0, std::fabs(z[j]));
        zp[j] += h;
        VectorXd Fp;
        if (!residual(zp, s, Fp)) {
          return false;
        }
        J.col(j) = (Fp - F) / h;
      }
      const VectorXd dz = J.fullPivLu().solve(-F);
      if (!dz.allFinite()) {
        return false;
      }
      double t = 1.0;
      bool improved = false;
      for (int k = 0; k < 10; ++k) {
        VectorXd zt = z + t * dz;
        VectorXd Ft;
        if (residual(zt, s, Ft) && Ft.lpNorm<Eigen::Infinity>() < r) {
          z = zt;
          F = Ft;
          improved = true;
          break;
        }
        t *= 0.5;
      }
      if (!improved) {
        return false;
      }
    }
    return false;
  }

  // The flexures' strain energy at z (scaled), from their sampled shapes.
  double strain_energy(const VectorXd& z) {
    double U = 0.0;
    for (std::size_t i = 0; i < beams_.size(); ++i) {
      const FlexureBeam& b = beams_[i];
      if (b.model != FlexureModel::kExact) {
        // The ladder's models here give a tip, not a shape: no strain energy (docs).
        return std::numeric_limits<double>::quiet_NaN();
      }
      const Eigen::Vector3d w = z.segment<3>(flexure_offset() + 3 * static_cast<int>(i));
      std::vector<ShapePoint> shape;
      BeamTip tip;
      if (!integrate(b, w, tip, &shape, kEnergySamples) || shape.size() < 2) {
        throw NoConvergence("flexure '" + b.flexure->name + "': its shape could not be sampled");
      }
      // m(s) = m0 + Nx y(s) - Ny x(s) in the beam's frame (m' = Nx sin theta - Ny cos theta).
      for (std::size_t k = 1; k < shape.size(); ++k) {
        const ShapePoint& p0 = shape[k - 1];
        const ShapePoint& p1 = shape[k];
        const double ma = w[0] + w[1] * p0.y - w[2] * p0.x;
        const double mb = w[0] + w[1] * p1.y - w[2] * p1.x;
        // m^2/(2 EI(s)) (a taper's EI at each sample; m = EI (theta' - kappa0) for a curved one).
        const double EIa = shape.size() == b.sample_EI.size() ? b.sample_EI[k - 1] : b.EI;
        const double EIb = shape.size() == b.sample_EI.size() ? b.sample_EI[k] : b.EI;
        U += 0.5 * (ma * ma / (2.0 * EIa) + mb * mb / (2.0 * EIb)) * (p1.s - p0.s);
        if (std::isfinite(b.EA)) {
          // The axial strain energy N_a^2/(2 EA), N_a = N . t (Reissner; docs/extensible.md).
          const double na = w[1] * std::cos(p0.theta) + w[2] * std::sin(p0.theta);
          const double nb = w[1] * std::cos(p1.theta) + w[2] * std::sin(p1.theta);
          U += 0.5 * (na * na + nb * nb) / (2.0 * b.EA) * (p1.s - p0.s);
        }
      }
    }
    return U;
  }

  // Every flexure's end loads, largest stress and shape at z (general_analysis.h), SI, and
  // their loads on the ground added to `ground`. An exact flexure's bending moment and axial
  // force are those of its elastica along kEnergySamples samples (m = m0 + Nx y - Ny x,
  // N_a = N . t in the root frame), the largest |sigma| refined by a parabola through the largest
  // sample and its neighbours; a model flexure (mixed) gives its ends' (its model has no shape).
  std::vector<FlexurePointResult> flexure_results(const VectorXd& z, PointLoad& ground) {
    const VectorXd q = z.head(N_);
    const double L = a_.length_scale(), K = a_.energy_scale();
    std::vector<FlexurePointResult> out;
    for (std::size_t i = 0; i < beams_.size(); ++i) {
      const FlexureBeam& b = beams_[i];
      const Flexure& f = *b.flexure;
      const Eigen::Vector3d w = z.segment<3>(flexure_offset() + 3 * static_cast<int>(i));
      const double beta = b.direction + a_.body_rotation(q, f.a.body);
      const double c = std::cos(beta), sn = std::sin(beta);
      const Eigen::Vector2d N(c * w[1] - sn * w[2], sn * w[1] + c * w[2]);  // global, scaled
      const Eigen::Vector2d pa = a_.point_scaled(q, f.a), pb = a_.point_scaled(q, f.b);
      FlexurePointResult r;
      BeamTip tip;
      double m0 = w[0];
      if (b.model != FlexureModel::kExact) {
        // A CBCM flexure is marched from its root loads w = (m0, Nx, Ny); any other model takes
        // its tip loads w = (M_tip, Nx, Ny).
        const bool cbcm = b.model == FlexureModel::kCbcm;
        if (cbcm ? !cbcm_state(b, w, tip) : !model_state(b, w, tip)) {
          throw NoConvergence("flexure '" + f.name + "': its model has no tip at a recorded point");
        }
        if (!cbcm) m0 = w[0] - w[1] * tip.y + w[2] * tip.x;
        const double axial_b = w[1] * std::cos(tip.theta) + w[2] * std::sin(tip.theta);
        end_stresses(r, f, b.length * L, m0 * K, w[1] * K / L, tip.m * K, axial_b * K / L);
        r.shape_x = {pa.x() * L, pb.x() * L};
        r.shape_y = {pa.y() * L, pb.y() * L};
      } else {
        std::vector<ShapePoint> shape;
        if (!integrate(b, w, tip, &shape, kEnergySamples, &report_integrator_) ||
            shape.size() != b.sample_width.size()) {
          throw NoConvergence("flexure '" + f.name + "': its shape could not be sampled");
        }
        r.max_from = "shape";
        std::vector<double> ms(shape.size()), ns(shape.size()), worst(shape.size());
        std::size_t k_max = 0;
        for (std::size_t k = 0; k < shape.size(); ++k) {
          const ShapePoint& p = shape[k];
          ms[k] = (w[0] + w[1] * p.y - w[2] * p.x) * K;
          ns[k] = (w[1] * std::cos(p.theta) + w[2] * std::sin(p.theta)) * K / L;
          const FibreStresses st =
              fibre_stresses(b.sample_width[k], b.sample_thickness[k], ms[k], ns[k]);
          worst[k] = std::max(std::fabs(st.pos), std::fabs(st.neg));
          if (worst[k] > worst[k_max]) k_max = k;
        }
        keep_most_stressed(r,
                           b.sample_width[k_max],
                           b.sample_thickness[k_max],
                           shape[k_max].s * L,
                           ms[k_max],
                           ns[k_max],
                           true);
        if (k_max > 0 && k_max + 1 < shape.size()) {
          // The parabola through the largest sample and its neighbours (equal spacing h): its
          // vertex at offset t h, t = (w- - w+)/(2 (w- - 2 w + w+)); m and N_a interpolated there.
          const double wm = worst[k_max - 1], w0 = worst[k_max], wp = worst[k_max + 1];
          const double den = wm - 2.0 * w0 + wp;
          if (den < 0.0) {
            const double t = std::clamp(0.5 * (wm - wp) / den, -1.0, 1.0);
            auto interp = [&](const std::vector<double>& v) {
              return v[k_max] + 0.5 * t * (v[k_max + 1] - v[k_max - 1]) +
                     0.5 * t * t * (v[k_max + 1] - 2.0 * v[k_max] + v[k_max - 1]);
            };
            const double h = shape[k_max + 1].s - shape[k_max].s;
            keep_most_stressed(r, f, (shape[k_max].s + t * h) * L, interp(ms), interp(ns), false);
          }
        }
        // Every 8th sample: 33 points of the shape, global.
        for (std::size_t k = 0; k < shape.size(); k += 8) {
          const ShapePoint& p = shape[k];
          r.shape_x.push_back((pa.x() + c * p.x - sn * p.y) * L);
          r.shape_y.push_back((pa.y() + sn * p.x + c * p.y) * L);
        }
      }
      // The beam pushes its root body with +N, +m0 and its tip body with -N, -m(tip).
      r.on_a = {N.x() * K / L, N.y() * K / L, m0 * K};
      r.on_b = {-N.x() * K / L, -N.y() * K / L, -tip.m * K};
      if (f.a.body == "ground") add_ground_reaction(ground, r.on_a, pa.x() * L, pa.y() * L);
      if (f.b.body == "ground") add_ground_reaction(ground, r.on_b, pb.x() * L, pb.y() * L);
      out.push_back(std::move(r));
    }
    return out;
  }

  // Linearises every exact flexure's tip in its root loads at z (sensitivity integration).
  bool linearise(const VectorXd& z) {
    linear_.clear();
    std::vector<TipLinearisation> lin(beams_.size());
    for (std::size_t i = 0; i < beams_.size(); ++i) {
      const FlexureBeam& b = beams_[i];
      if (b.model != FlexureModel::kExact) continue;
      const Eigen::Vector3d w = z.segment<3>(flexure_offset() + 3 * static_cast<int>(i));
      ChainForces forces;
      forces.m0 = w[0];
      forces.N = {Eigen::Vector2d(w[1], w[2])};
      forces.moment_drop = {0.0, 0.0};
      // Parameters m0, Nx, Ny: m0 enters the start state, N the segment's force.
      std::vector<ForceDerivative> d(3);
      d[0].dN = {Eigen::Vector2d(0.0, 0.0)};
      d[1].dN = {Eigen::Vector2d(1.0, 0.0)};
      d[2].dN = {Eigen::Vector2d(0.0, 1.0)};
      Eigen::Matrix<double, 4, Eigen::Dynamic> start = Eigen::Matrix<double, 4, 3>::Zero();
      start(3, 0) = 1.0;
      const std::vector<IntegrationPiece> pieces{IntegrationPiece{0, 0.0, b.length, 0.0, false}};
      TipState end;
      std::string error;
      if (!sensitivity_integrator_.integrate(
              b.chain, pieces, forces, d, Eigen::Vector4d(0, 0, 0, w[0]), start, end, error)) {
        return false;
      }
      lin[i].w0 = w;
      lin[i].tip0 = Eigen::Vector4d(end.x, end.y, end.theta, end.m);
      lin[i].S = end.sensitivity.leftCols(3);
    }
    linear_ = std::move(lin);
    return true;
  }

  // The Jacobian of the residual in z at (z, s), and its column in s (-e at the input's row):
  // central differences with every exact flexure's tip linearised in its loads.
  bool linearised_jacobian(const VectorXd& z, double s, MatrixXd& J) {
    if (!linearise(z)) {
      return false;
    }
    J.resize(size(), size());
    bool ok = true;
    for (int j = 0; j < size() && ok; ++j) {
      const double h = kLinearisedStep * std::max(1.0, std::fabs(z[j]));
      VectorXd zp = z, zm = z;
      zp[j] += h;
      zm[j] -= h;
      VectorXd Fp, Fm;
      ok = residual(zp, s, Fp) && residual(zm, s, Fm);
      if (ok) J.col(j) = (Fp - Fm) / (2.0 * h);
    }
    linear_.clear();
    return ok;
  }

  // Flexure i's shape at the arc lengths `stations` (scaled) from its root loads w.
  std::vector<ShapePoint> shape_at(std::size_t i,
                                   const Eigen::Vector3d& w,
                                   const std::vector<double>& stations) {
    const FlexureBeam& b = beams_[i];
    ChainForces forces;
    forces.m0 = w[0];
    forces.N = {Eigen::Vector2d(w[1], w[2])};
    forces.moment_drop = {0.0, 0.0};
    const std::vector<IntegrationPiece> pieces{IntegrationPiece{0, 0.0, b.length, 0.0, false}};
    TipState end;
    std::string error;
    std::vector<ShapePoint> shape;
    const Eigen::Matrix<double, 4, Eigen::Dynamic> none(4, 0);
    if (!shape_integrator_.integrate(b.chain,
                                     pieces,
                                     forces,
                                     {},
                                     Eigen::Vector4d(0, 0, 0, w[0]),
                                     none,
                                     end,
                                     error,
                                     &stations,
                                     &shape)) {
      throw NoConvergence("flexure '" + b.flexure->name + "': its shape could not be integrated (" +
                          error + ")");
    }
    return shape;
  }

  // A CBCM flexure's shape at the arc lengths `stations` (scaled) from its root loads w: each
  // element's BCM cubic between its nodes (y(xi) = (3y - theta) xi^2 + (theta - 2y) xi^3 per
  // element length, its axial displacement x spread evenly), root frame, scaled.
  static std::vector<ShapePoint> cbcm_shape_at(const FlexureBeam& b,
                                               const Eigen::Vector3d& w,
                                               const std::vector<double>& stations) {
    BeamTip tip;
    CbcmMarchResult march;
    if (!cbcm_state(b, w, tip, &march)) {
      throw InvalidInput("the CBCM march failed at these loads");
    }
    const int n = b.elements;
    const double l = b.length, h = 1.0 / n;
    std::vector<ShapePoint> shape;
    shape.reserve(stations.size());
    for (double st : stations) {
      const double u = std::clamp(st / l, 0.0, 1.0) * n;
      const int j = std::min(static_cast<int>(u), n - 1);
      const double xi = u - j;
      const ChainPose& a = march.nodes[static_cast<std::size_t>(j)];
      const ChainPose& e = march.nodes[static_cast<std::size_t>(j + 1)];
      const double c = std::cos(a.theta), sn = std::sin(a.theta);
      const double dx = (e.x - a.x) / h, dy = (e.y - a.y) / h;
      const double ax = c * dx + sn * dy;  // 1 + x_j
      const double yj = -sn * dx + c * dy;
      const double th = e.theta - a.theta;
      const double Y = (3.0 * yj - th) * xi * xi + (th - 2.0 * yj) * xi * xi * xi;
      const double dY = 2.0 * (3.0 * yj - th) * xi + 3.0 * (th - 2.0 * yj) * xi * xi;
      const double lx = h * ax * xi, ly = h * Y;
      ShapePoint p;
      p.s = st;
      p.x = l * (a.x + c * lx - sn * ly);
      p.y = l * (a.y + sn * lx + c * ly);
      p.theta = a.theta + std::atan2(dY, ax);
      shape.push_back(p);
    }
    return shape;
  }

  // The verdicts of the equilibrium z at input s (exact_stability.h): each exact flexure's own
  // second variation with its ends held, plus the condensed stiffness of the mechanism's free
  // directions with the input held (displacement control) or free under its dead load (force
  // control).
  PointVerdicts judge(const VectorXd& z, double s, double critical_tolerance) {
    PointVerdicts v;
    MatrixXd J;
    if (!linearised_jacobian(z, s, J)) {
      v.displacement_control = not_checked_stability(
          "the exact model's linearisation failed at this point (an integration did not finish)");
      v.force_control = v.displacement_control;
      return v;
    }
    const VectorXd q = z.head(N_);
    const int n = size();
    // Reference stiffness: the springs' unloaded stiffness and every flexure's linear bending
    // stiffness in its current root frame (12 EI/l^3, -6 EI/l^2, 4 EI/l across and in rotation,
    // Euler-Bernoulli; 3 EI/l^3 across a pinned tip), on the tip's motion dq. Along the flexure
    // it counts the transverse value: an inextensible flexure's axial stiffness is infinite, and
    // even EA/l would dwarf the bending and leave every bending direction's margin near 0.
    MatrixXd B = a_.unloaded_stiffness(q);
    int flexures_judged = 0;
    int flexures_unjudged = 0;
    int index_flexures = 0;
    double margin_flexures = 1.0;
    std::string flexure_notes;
    for (std::size_t i = 0; i < beams_.size(); ++i) {
      const FlexureBeam& b = beams_[i];
      const int o = flexure_offset() + 3 * static_cast<int>(i);
      const double l = b.length, EI = b.EI;
      const int rows = b.pinned_tip ? 2 : 3;
      const MatrixXd T = -J.block(o, 0, rows, N_);  // d(tip pose in the root frame)/dq
      MatrixXd K = MatrixXd::Zero(rows, rows);
      K(0, 0) = (b.pinned_tip ? 3.0 : 12.0) * EI / (l * l * l);
      if (b.pinned_tip) {
        K(1, 1) = 3.0 * EI / (l * l * l);
      } else {
        K(1, 1) = 12.0 * EI / (l * l * l);
        K(1, 2) = K(2, 1) = -6.0 * EI / (l * l);
        K(2, 2) = 4.0 * EI / l;
      }
      B += T.transpose() * K * T;
      if (!b.root_loads()) {
        flexure_notes += "; flexure '" + b.flexure->name + "' (" +
                         std::string(flexure_model_name(b.model)) +
                         ") judged by its tip relation only";
        continue;
      }
      // The flexure with both ends held: a clamped-clamped (or clamped-pinned) chain under the
      // end force its far body puts on its tip, which acts like a dead load in the second
      // variation (docs/stability.md "What is computed").
      const Eigen::Vector3d w = z.segment<3>(o);
      SegmentChain chain = b.chain;
      chain.end = b.pinned_tip ? EndCondition::kPinned : EndCondition::kFixed;
      StabilityOptions so;
      so.critical_tolerance = critical_tolerance;
      Stability fv;
      if (b.model == FlexureModel::kCbcm) {
        // The CBCM has no energy of its own here (cbcm_path.h: not assembled): the elastica's
        // second variation on the CBCM's shape (each element's cubic), at the verdict's
        // stations without refinement. Its margin is the exact one's to the CBCM's accuracy
        // (docs/mechanisms.md "The inclined bistable beam with the CBCM").
        try {
          const Reaction support{w[1], w[2], 0.0};
          fv = equilibrium_stability(
              chain, support, cbcm_shape_at(b, w, stability_stations(chain, support, so)), so);
          fv.message += " (the elastica's second variation on the CBCM's shape)";
        } catch (const InvalidInput& e) {
          fv = not_checked_stability(std::string("the CBCM's shape could not be judged: ") +
                                     e.what());
        }
      } else {
        fv = equilibrium_stability(
            chain,
            Reaction{w[1], w[2], 0.0},
            [&](const std::vector<double>& st) { return shape_at(i, w, st); },
            so);
      }
      if (!fv.judged()) {
        ++flexures_unjudged;
        flexure_notes += "; flexure '" + b.flexure->name + "' not judged: " + fv.message;
        continue;
      }
      ++flexures_judged;
      index_flexures += fv.index;
      margin_flexures = std::min(margin_flexures, fv.margin);
      if (fv.index > 0) {
        flexure_notes += "; flexure '" + b.flexure->name + "' unstable with its ends held (index " +
                         std::to_string(fv.index) + ")";
      }
    }
    const MatrixXd Jg = a_.constraint_jacobian(q);
    auto condensed = [&](const MatrixXd& Jsys, const MatrixXd& Z, const std::string& control) {
      CondensedVerdict c;
      if (Z.cols() > 0) {
        MatrixXd rhs = MatrixXd::Zero(n, Z.cols());
        rhs.topRows(N_) = Z;
        const MatrixXd X = Jsys.fullPivLu().solve(rhs);
        c = condensed_verdict(Z.transpose() * X.topRows(N_), Z.transpose() * B * Z);
      }
      const int index = c.index + index_flexures;
      const double margin = std::min(c.margin, margin_flexures);
      // An unjudged flexure leaves the index a lower bound (the inertia adds up): unstable is
      // still a verdict, stable is not.
      Stability st = flexures_unjudged > 0 && index == 0
                         ? not_checked_stability(
                               "no negative direction found, but not every flexure could be "
                               "judged with its ends held")
                         : classify_stability(index, margin, critical_tolerance, "the mechanism");
      st.message += fmt::format(
          " under {} control (exact model: {} free direction(s) of the bodies, condensed "
          "stiffness index {} and margin {:.6g} against the unloaded flexures and springs; {} "
          "flexure(s) with their ends held, index {}, lowest margin {:.6g}{})",
          control,
          Z.cols(),
          c.index,
          c.margin,
          flexures_judged,
          index_flexures,
          margin_flexures,
          flexure_notes);
      return st;
    };
    MatrixXd Jd(Jg.rows() + 1, N_);
    Jd << Jg, a_.input_gradient(q).transpose();
    v.displacement_control = condensed(J, exact_null_space(Jd, N_), "displacement");
    // Force control: the input coordinate free, its load lambda given: the column of lambda
    // becomes the column of s.
    MatrixXd Jf = J;
    Jf.col(N_ + m_).setZero();
    Jf(N_ + m_, N_ + m_) = -1.0;
    v.force_control = condensed(Jf, exact_null_space(Jg, N_), "force");
    return v;
  }

  double residual() const { return residual_; }

 private:
  const PrbmAssembly& a_;
  int N_, m_;
  std::vector<FlexureBeam> beams_;
  ElasticaIntegrator integrator_;
  // For flexure_state: the integrator keeps state between calls (its step size), so the reports
  // use their own and leave the Newton iteration's numbers exactly those of the exact model.
  ElasticaIntegrator report_integrator_;
  // The verdicts' own integrators (sensitivities; shapes), for the same reason.
  ElasticaIntegrator sensitivity_integrator_;
  ElasticaIntegrator shape_integrator_;
  std::vector<TipLinearisation> linear_;  // non-empty: residual() uses these tips
  double residual_ = 0.0;
};

Stability exact_not_checked() {
  return not_checked_stability("not judged (GeneralExactOptions::judge_stability is off)");
}

}  // namespace

// The joints' structure without the flexures (a mechanism with an extensible flexure): independent
// joints, a freedom to move, an input that moves to first order (or a start_rotation). Returns
// the degrees of freedom with the input free.
int check_joints(const GeneralMechanism& mechanism, const PrbmAssembly& A) {
  const int N = A.coordinate_count();
  const VectorXd q0 = VectorXd::Zero(N);
  const MatrixXd Jg = A.constraint_jacobian(q0);
  auto rank = [](const MatrixXd& M) {
    if (M.rows() == 0) return 0;
    Eigen::JacobiSVD<MatrixXd> svd(M);
    const VectorXd& sv = svd.singularValues();
    int r = 0;
    for (int i = 0; i < sv.size(); ++i) r += sv[i] > 1e-9 * std::max(1.0, sv[0]) ? 1 : 0;
    return r;
  };
  const int rg = rank(Jg);
  if (rg < Jg.rows()) {
    throw InvalidInput(mechanism.where(0) +
                       "the joints are redundant in the described "
                       "configuration (over-constrained mechanisms are not supported)");
  }
  const int dof = N - rg;
  MatrixXd Jd(Jg.rows() + 1, N);
  Jd << Jg, A.input_gradient(q0).transpose();
  if (dof == 0) {
    throw InvalidInput(mechanism.where(mechanism.input.line) +
                       "input: the joints leave the mechanism no freedom to move");
  }
  if (rank(Jd) == rg && mechanism.input.start_rotation.empty()) {
    throw InvalidInput(mechanism.where(mechanism.input.line) +
                       "input: the input coordinate cannot move to first order in the described "
                       "configuration (a dead point); give the input a start_rotation");
  }
  return dof;
}

void GeneralExactOptions::validate() const {
  if (!(tolerance > 0.0) || !(tolerance < 1e-3)) {
    throw InvalidInput("GeneralExactOptions.tolerance must be in (0, 1e-3)");
  }
  if (!(critical_tolerance >= 0.0) || !std::isfinite(critical_tolerance)) {
    throw InvalidInput("GeneralExactOptions.critical_tolerance must be finite and >= 0");
  }
  if (max_newton_iterations < 1 || max_step_halvings < 0) {
    throw InvalidInput(
        "GeneralExactOptions.max_newton_iterations must be >= 1, max_step_halvings >= 0");
  }
  if (max_steps < 1 || !(max_step > 0.0) || !(max_step <= 1.0)) {
    throw InvalidInput("GeneralExactOptions.max_steps must be >= 1 and max_step in (0, 1]");
  }
}

namespace {

// The exact system with each flexure's model (`models`, `elements`: one per flexure, or empty for
// every flexure exact); `reports` (if given, one per flexure) get each recorded point's tip loads
// and tips.
GeneralPrbmResult solve_exact_system(const GeneralMechanism& mechanism,
                                     const GeneralExactOptions& options,
                                     const std::vector<FlexureModel>& models,
                                     const std::vector<int>& elements,
                                     std::vector<FlexureModelReport>* reports) {
  options.validate();
  mechanism.validate();
  const PrbmAssembly A(mechanism, /*assemble_flexures=*/false);
  const bool extensible = std::any_of(mechanism.flexures.begin(),
                                      mechanism.flexures.end(),
                                      [](const Flexure& f) { return f.extensible; });
  // The structural checks on the PRB linkage, unless a flexure is extensible: its PRBM element is
  // inextensible and may lock a linkage that the extensible beam lets move (a beam between two
  // bodies whose distance the joints fix), so the joints alone are checked then.
  const int dof = extensible ? check_joints(mechanism, A) : check_general_mechanism(mechanism);
  ExactSystem S(mechanism, A, models, elements);
  const int N = A.coordinate_count();
  const int m = A.constraint_count();
  GeneralPrbmResult result;
  result.degrees_of_freedom = dof;
  const std::vector<std::string> names = A.body_names();
  result.body_names = names;

  const Input& in = mechanism.input;
  std::vector<double> grid(static_cast<std::size_t>(in.count));
  for (int i = 0; i < in.count; ++i) {
    grid[static_cast<std::size_t>(i)] =
        A.input_scaled(in.start + (in.stop - in.start) * i / (in.count - 1));
  }

  VectorXd z = VectorXd::Zero(S.size());
  int iterations = 0;
  double s = A.input(z.head(N));
  auto fail = [&](const std::string& why) {
    result.termination = Termination::kNoConvergence;
    result.message = why;
    result.iterations = iterations;
    return result;
  };
  if (!in.start_rotation.empty()) {
    for (const auto& [body, angle] : in.start_rotation) {
      const auto it = std::find(names.begin(), names.end(), body);
      z[3 * (it - names.begin()) + 2] = angle;
    }
    // Under displacement control, where the mechanism's PRBM (every flexure its PRB element)
    // reaches the first input value from the same start_rotation, Newton starts from its state
    // (flexure_stress.h, prbm_point_statics): the bodies' poses, the input load, the joints'
    // multipliers and each flexure's end loads. The rotations alone leave a flexure that the
    // PRBM bends hard (a long fixed-pinned segment between two turned links: slp, plp) straight
    // and unloaded, and Newton then finds another equilibrium (a mode of that segment).
    if (in.control == InputControl::kDisplacement && !extensible) {
      GeneralMechanism prbm = mechanism;
      for (Flexure& f : prbm.flexures) f.model = FlexureModel::kPrbm;
      try {
        const GeneralPrbmResult first = solve_general_prbm(prbm);
        if (!first.points.empty() && first.body_names == names) {
          const GeneralPrbmPoint& p0 = first.points.front();
          const PrbmPointStatics st = prbm_point_statics(prbm, p0);
          const double L = A.length_scale(), K = A.energy_scale();
          for (std::size_t b = 0; b < names.size(); ++b) {
            z[3 * static_cast<int>(b)] = p0.body_x[b] / L;
            z[3 * static_cast<int>(b) + 1] = p0.body_y[b] / L;
            z[3 * static_cast<int>(b) + 2] = p0.body_phi[b];
          }
          for (int k = 0; k < m; ++k) z[N + k] = st.multipliers[static_cast<std::size_t>(k)];
          z[N + m] = A.load_scaled(p0.input_load);
          for (std::size_t i = 0; i < mechanism.flexures.size(); ++i) {
            const Flexure& f = mechanism.flexures[i];
            const PrbmFlexureLoads& w = st.flexures[i];
            const Vec2 pa = mechanism.point(f.a), pb = mechanism.point(f.b);
            const double beta =
                std::atan2(pb.y - pa.y, pb.x - pa.x) + A.body_rotation(z.head(N), f.a.body);
            const double c = std::cos(beta), sn = std::sin(beta);
            const int o = S.flexure_offset() + 3 * static_cast<int>(i);
            const bool exact = models.empty() || models[i] == FlexureModel::kExact;
            // An exact flexure's unknowns are its root loads, a model flexure's its tip loads.
            z[o] =
                (exact ? w.root_moment : w.root_moment - (w.tip_dx * w.Ny - w.tip_dy * w.Nx)) / K;
            z[o + 1] = (c * w.Nx + sn * w.Ny) * L / K;
            z[o + 2] = (-sn * w.Nx + c * w.Ny) * L / K;
          }
        }
      } catch (const std::exception&) {
        // No PRBM start (a fixed-guided flexure, a PRBM that does not reach the input): the
        // rotations alone.
      }
    }
    // Displacement control: the first grid value; force control: the input where the rotations
    // put it, from which the path follows the load.
    s = in.control == InputControl::kDisplacement ? grid.front() : A.input(z.head(N));
    if (!S.newton(z, s, options.tolerance, options.max_newton_iterations, &iterations)) {
      return fail(
          "Newton did not converge at the first input value from the given "
          "start_rotation");
    }
  } else if (!S.newton(z, s, options.tolerance, options.max_newton_iterations, &iterations)) {
    return fail("Newton did not converge at the described configuration");
  }

  // Natural-parameter continuation with a secant predictor; the input step is halved on failure.
  VectorXd z_prev = z;
  double s_prev = s;
  auto advance = [&](double target) {
    double step = target - s;
    int halvings = 0;
    while (s != target) {
      const double s_next = std::fabs(target - s) <= std::fabs(step) ? target : s + step;
      VectorXd trial = z;
      if (s != s_prev) {
        trial += (z - z_prev) * ((s_next - s) / (s - s_prev));
      }
      if (S.newton(trial, s_next, options.tolerance, options.max_newton_iterations, &iterations)) {
        z_prev = z;
        s_prev = s;
        z = trial;
        s = s_next;
        continue;
      }
      if (++halvings > options.max_step_halvings) {
        return false;
      }
      step *= 0.5;
    }
    return true;
  };

  std::size_t reported = 0;  // options.progress: points reported, never decreasing
  auto record = [&]() {
    GeneralPrbmPoint pt;
    const VectorXd q = z.head(N);
    pt.input = A.input_si(s);
    pt.input_load = A.load_si(z[N + m]);
    const double strain = S.strain_energy(z);
    pt.spring_energy = A.energy_si(A.spring_energy(q) + strain);
    pt.energy = A.energy_si(A.energy(q) + strain);
    if (options.judge_stability) {
      PointVerdicts v = S.judge(z, s, options.critical_tolerance);
      pt.displacement_control = std::move(v.displacement_control);
      pt.force_control = std::move(v.force_control);
    } else {
      pt.displacement_control = exact_not_checked();
      pt.force_control = exact_not_checked();
    }
    for (int b = 0; b < A.described_body_count(); ++b) {
      pt.body_x.push_back(q[3 * b] * A.length_scale());
      pt.body_y.push_back(q[3 * b + 1] * A.length_scale());
      pt.body_phi.push_back(q[3 * b + 2]);
    }
    fill_point_results(mechanism, A, q, z.segment(N, m), /*assembled_flexures=*/false, pt);
    pt.flexures = S.flexure_results(z, pt.ground_reaction);
    if (reports != nullptr) {
      for (std::size_t i = 0; i < S.flexure_count(); ++i) {
        FlexureTipLoad load;
        FlexureTip tip;
        if (!S.flexure_state(z, i, load, tip)) {
          const double nan = std::numeric_limits<double>::quiet_NaN();
          load = {nan, nan, nan};
          tip = {nan, nan, nan};
        }
        (*reports)[i].loads.push_back(load);
        (*reports)[i].tips.push_back(tip);
      }
    }
    result.points.push_back(std::move(pt));
    if (options.progress) {
      reported = std::min(std::max(reported, result.points.size()), grid.size());
      options.progress(reported, grid.size());
    }
  };

  // The pseudo-arclength path from (z_start, s_start): force control, and displacement control
  // where the natural-parameter continuation below fails (a limit point of the input).
  auto arclength_path = [&](const VectorXd& z_start, double s_start, bool force) {
    // Force control: pseudo-arclength continuation of (z, s) through the limit points of the
    // input load (where a dead load makes the mechanism snap), as the PRBM's path
    // (general_prbm.cpp): the curve F(z, s) = 0, the grid values of lambda recorded where the path
    // crosses them, limit points located by bisection on the tangent's lambda component. The
    // Jacobian is the linearised one (ExactSystem::linearised_jacobian); the arclength is
    // measured on the bodies' coordinates, lambda and s only (the joints' multipliers and the
    // flexures' loads follow them and are on other scales).
    const int n = S.size();
    // The controlled quantity in y = (z, s): lambda (force control) or s.
    const int p = force ? N + m : n;
    VectorXd weight = VectorXd::Zero(n + 1);
    weight.head(N).setOnes();
    weight[p] = 1.0;
    weight[n] = 1.0;
    auto F_of = [&](const VectorXd& y, VectorXd& F) { return S.residual(y.head(n), y[n], F); };
    auto J_of = [&](const VectorXd& y, MatrixXd& J) {
      MatrixXd Jz;
      if (!S.linearised_jacobian(y.head(n), y[n], Jz)) return false;
      J = MatrixXd::Zero(n, n + 1);
      J.leftCols(n) = Jz;
      J(N + m, n) = -1.0;
      return true;
    };
    ArclengthPath path(
        {n + 1, F_of, J_of, weight},
        {options.tolerance, options.max_newton_iterations, options.max_step, options.max_steps});
    std::vector<double> loads = grid;  // the controlled quantity's grid values, scaled
    if (force) {
      for (int i = 0; i < in.count; ++i) {
        loads[static_cast<std::size_t>(i)] =
            A.load_scaled(in.start + (in.stop - in.start) * i / (in.count - 1));
      }
    }
    ArclengthPath::Follow how;
    how.controlled = p;
    how.limit = [&](const VectorXd& yl) {
      result.limit_inputs.push_back(A.input_si(yl[n]));
      result.limit_loads.push_back(A.load_si(yl[N + m]));  // lambda, whichever is controlled
    };
    ArclengthPath::Follow recording = how;
    recording.grid = &loads;
    recording.record = [&](const VectorXd& y) {
      z = y.head(n);
      s = y[n];
      record();
    };
    // A path that keeps crossing the grid (a closed curve of a linkage driven past the end of its
    // travel) has turned back for good: stop rather than go round it.
    recording.give_up = [&] {
      return result.points.size() > 4 * static_cast<std::size_t>(in.count);
    };
    VectorXd y(n + 1);
    y << z_start, s_start;
    Termination end = Termination::kConverged;
    double worst = 0.0;
    if (y[p] != loads.front()) {
      end = path.follow(y, loads.front(), how);
    } else {
      worst = S.residual();
    }
    if (end == Termination::kConverged) {
      recording.record(y);
      result.limit_inputs.clear();
      result.limit_loads.clear();
      end = path.follow(y, loads.back(), recording);
    }
    const int steps = path.steps();
    result.iterations = iterations + path.iterations();
    result.termination = end;
    if (end == Termination::kLimitPoint) {
      result.message =
          std::string("the exact model's path did not reach the end of the ") +
          (force ? "load" : "input") + " range after " + std::to_string(steps) + " steps" +
          (result.limit_inputs.empty() ? std::string()
                                       : "; it turned back at a limit point at input " +
                                             input_value_text(in, result.limit_inputs.front()));
    } else if (end == Termination::kNoConvergence) {
      result.message = "the exact model's continuation failed after " + std::to_string(steps) +
                       " steps (" + std::to_string(result.points.size()) + " points recorded for " +
                       std::to_string(in.count) + " grid values)";
      // Driven past the end of its travel, the path turns back at a limit point of the input and
      // wanders along other branches (another assembly of the linkage) until it fails: say where
      // the travel ended, which is what the user can act on.
      if (!result.limit_inputs.empty()) {
        result.message += std::string("; the ") + (force ? "load" : "input") +
                          " turned back at a limit point at input " +
                          input_value_text(in, result.limit_inputs.front()) +
                          (force ? std::string(" (the mechanism snaps there)")
                                 : std::string(" (the end of the mechanism's travel this way: end "
                                               "the input range before it)"));
      }
    }
    // Equilibria of the unloaded mechanism: sign changes of lambda along the path, by Newton
    // with lambda = 0 (lambda, not the controlled component: under displacement control the
    // path's parameter is the input coordinate).
    std::vector<VectorXd> failed;
    for (const VectorXd& ye : path.zeros_along(N + m, &failed)) {
      const double se = A.input_si(ye[n]);
      if (!result.equilibria.empty() &&
          std::fabs(result.equilibria.back().input - se) <
              1e-9 * std::max(1.0, std::fabs(se)) * (A.input_is_angle() ? 1.0 : A.length_scale())) {
        continue;
      }
      GeneralEquilibrium e;
      e.input = se;
      e.energy = A.energy_si(A.energy(ye.head(N)) + S.strain_energy(ye.head(n)));
      e.stability = options.judge_stability
                        ? S.judge(ye.head(n), ye[n], options.critical_tolerance).force_control
                        : exact_not_checked();
      result.equilibria.push_back(std::move(e));
    }
    for (const VectorXd& yf : failed) {
      result.warn(WarningKind::kOther,
                  "an exact equilibrium near input " + fmt(A.input_si(yf[n])) +
                      " was bracketed but Newton did not converge");
    }
    worst = std::max(worst, path.worst_residual());
    result.residual = std::max(worst, S.residual());
    return result;
  };
  if (in.control == InputControl::kForce) {
    return arclength_path(z, s, true);
  }
  const VectorXd z_start = z;
  const double s_start = s;

  std::vector<std::pair<double, VectorXd>> path;  // (s, z) at the grid points
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (!advance(grid[i])) {
      // A limit point of the input (or a step Newton cannot make): the whole path again by
      // arclength, which passes limit points and records the grid values where it crosses them.
      GeneralPrbmResult natural = result;
      std::vector<FlexureModelReport> natural_reports;
      if (reports != nullptr) {
        natural_reports = *reports;
        for (FlexureModelReport& rep : *reports) {
          rep.loads.clear();
          rep.tips.clear();
        }
      }
      result.points.clear();
      GeneralPrbmResult again = arclength_path(z_start, s_start, false);
      if (again.converged() || again.points.size() > natural.points.size()) {
        if (again.converged()) {
          again.warn(WarningKind::kOther,
                     "the exact model's natural-parameter continuation stopped before input " +
                         fmt(A.input_si(grid[i])) +
                         "; the path was followed by arclength instead (through limit points)");
        }
        return again;
      }
      result = std::move(natural);
      if (reports != nullptr) *reports = std::move(natural_reports);
      result.iterations = iterations;
      result.termination = Termination::kNoConvergence;
      result.message = "the exact model's continuation failed before input " +
                       fmt(A.input_si(grid[i])) + " (" + std::to_string(result.points.size()) +
                       " of " + std::to_string(in.count) + " points)";
      return result;
    }
    record();
    path.emplace_back(s, z);
  }

  // Equilibria: sign changes of the input load between grid points, refined by the secant
  // method on s (each evaluation a converged point).
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    double s0 = path[i].first, s1 = path[i + 1].first;
    double l0 = path[i].second[N + m], l1 = path[i + 1].second[N + m];
    if (!(l0 * l1 <= 0.0)) {
      continue;
    }
    z = path[i].second;
    s = s0;
    z_prev = z;
    s_prev = s;
    bool ok = true;
    for (int k = 0; k < 60 && std::fabs(s1 - s0) > 1e-13 && l1 != l0; ++k) {
      const double s_new = s1 - l1 * (s1 - s0) / (l1 - l0);
      if (!advance(s_new)) {
        ok = false;
        break;
      }
      s0 = s1;
      l0 = l1;
      s1 = s;
      l1 = z[N + m];
      if (std::fabs(l1) < options.tolerance) {
        break;
      }
    }
    if (!ok) {
      result.warn(WarningKind::kOther,
                  "an exact equilibrium near input " + fmt(A.input_si(path[i].first)) +
                      " was bracketed but not refined");
      continue;
    }
    GeneralEquilibrium e;
    e.input = A.input_si(s);
    e.energy = A.energy_si(A.energy(z.head(N)) + S.strain_energy(z));
    e.stability = options.judge_stability ? S.judge(z, s, options.critical_tolerance).force_control
                                          : exact_not_checked();
    result.equilibria.push_back(std::move(e));
  }
  result.iterations = iterations;
  result.residual = S.residual();
  result.termination = Termination::kConverged;
  return result;
}

}  // namespace

GeneralPrbmResult solve_general_exact(const GeneralMechanism& mechanism,
                                      const GeneralExactOptions& options) {
  return solve_exact_system(mechanism, options, {}, {}, nullptr);
}

namespace {

std::string rung_title(FlexureModel m, int elements) {
  switch (m) {
    case FlexureModel::kLinear:
      return "linear theory";
    case FlexureModel::kBcm:
      return "the BCM";
    case FlexureModel::kPrbm3r:
      return "PR-3R (Su)";
    case FlexureModel::kCbcm:
      return fmt::format("the CBCM ({} elements)", elements);
    case FlexureModel::kChain:
      return fmt::format("the chain algorithm ({} elements)", elements);
    case FlexureModel::kPrbm:
      return "its PRBM element";
    case FlexureModel::kExact:
      return "the exact elastica";
    default:
      return std::string(flexure_model_name(m));
  }
}

// The largest mapped error of `model` over the loads of a report (infinite where one is missing);
// `unmapped` gets how many points have none.
double worst_mapped(FlexureModel model,
                    int elements,
                    const FlexureModelReport& r,
                    int* unmapped = nullptr) {
  double worst = 0.0;
  int missing = 0;
  for (const FlexureTipLoad& load : r.loads) {
    const double e = mapped_flexure_error(model, elements, load);
    if (std::isnan(e)) {
      ++missing;
    } else {
      worst = std::max(worst, e);
    }
  }
  if (unmapped != nullptr) *unmapped = missing;
  return missing > 0 ? std::numeric_limits<double>::infinity() : worst;
}

std::string passed_over(FlexureModel model, const FlexureModelReport& r) {
  int missing = 0;
  const double worst = worst_mapped(model, 6, r, &missing);
  if (missing > 0) {
    return fmt::format("{} (no mapped error at {} of {} points: a load off the map)",
                       rung_title(model, 6),
                       missing,
                       r.loads.size());
  }
  return fmt::format("{} (mapped error up to {:.2g} l)", rung_title(model, 6), worst);
}

std::string joined(const std::vector<std::string>& parts) {
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? ", " : "") + parts[i];
  return out;
}

}  // namespace

GeneralPrbmResult solve_general_mixed(const GeneralMechanism& mechanism,
                                      const GeneralExactOptions& options) {
  mechanism.validate();
  const std::size_t F = mechanism.flexures.size();
  const std::vector<FlexureModel>& ladder = auto_ladder();
  std::vector<FlexureModel> models(F);
  std::vector<int> elements(F, 6);
  std::vector<std::size_t> rung(F, 0);  // auto: index into the ladder (its size: exact)
  std::vector<std::vector<std::string>> passed(F);
  for (std::size_t i = 0; i < F; ++i) {
    const Flexure& f = mechanism.flexures[i];
    if (f.model != FlexureModel::kExact && (f.curved() || f.tapered())) {
      throw InvalidInput(mechanism.where(f.line) + "flexure '" + f.name +
                         "': " + (f.curved() ? "initially curved" : "tapered") + ", but model '" +
                         std::string(flexure_model_name(f.model)) +
                         "': the mixed model's other models (the ladder's and the PRBM "
                         "cantilever's) are straight uniform beams; give it model = \"exact\"");
    }
    if (f.model == FlexureModel::kPrbm && f.prbm == PrbmKind::kFixedGuided) {
      throw InvalidInput(mechanism.where(f.line) + "flexure '" + f.name +
                         "': model 'prbm' in the mixed model needs a cantilever PRBM element "
                         "(small-length or fixed-pinned); the fixed-guided element has two "
                         "pivots: choose exact, linear, bcm, prbm3r, cbcm, chain or auto for it");
    }
    if (f.model == FlexureModel::kCbcm || f.model == FlexureModel::kChain) {
      elements[i] = f.model_elements();
    }
    models[i] = f.model == FlexureModel::kAuto ? ladder.front() : f.model;
  }
  GeneralPrbmResult result;
  std::vector<FlexureModelReport> reports;
  // Progress over the passes, never decreasing: a later pass reports no more than the first did.
  GeneralExactOptions pass_options = options;
  std::size_t reported = 0;
  if (options.progress) {
    pass_options.progress = [&](std::size_t done, std::size_t total) {
      reported = std::max(reported, done);
      options.progress(reported, total);
    };
  }
  // Each pass with a change moves at least one auto flexure up a rung: at most
  // F (ladder size) passes change something, and one more confirms.
  const std::size_t max_passes = F * ladder.size() + 1;
  for (std::size_t pass = 0; pass < max_passes; ++pass) {
    reports.assign(F, FlexureModelReport{});
    result = solve_exact_system(mechanism, pass_options, models, elements, &reports);
    bool changed = false;
    for (std::size_t i = 0; i < F; ++i) {
      const Flexure& f = mechanism.flexures[i];
      if (f.model != FlexureModel::kAuto || rung[i] >= ladder.size()) continue;
      if (!result.converged()) {
        // Some cheaper model has no answer along the path; which one is not known.
        passed[i].push_back(fmt::format("{} (the mechanism did not solve with it: {})",
                                        rung_title(models[i], 6),
                                        result.message));
        ++rung[i];
      } else {
        if (worst_mapped(models[i], 6, reports[i]) <= f.tolerance) continue;
        passed[i].push_back(passed_over(models[i], reports[i]));
        ++rung[i];
        // The cheapest higher rung within the tolerance at these loads.
        while (rung[i] < ladder.size() &&
               !(worst_mapped(ladder[rung[i]], 6, reports[i]) <= f.tolerance)) {
          passed[i].push_back(passed_over(ladder[rung[i]], reports[i]));
          ++rung[i];
        }
      }
      models[i] = rung[i] < ladder.size() ? ladder[rung[i]] : FlexureModel::kExact;
      changed = true;
    }
    if (!changed) break;
  }

  for (std::size_t i = 0; i < F; ++i) {
    const Flexure& f = mechanism.flexures[i];
    FlexureModelReport& r = reports[i];
    r.name = f.name;
    r.requested = f.model;
    r.model = models[i];
    r.elements = elements[i];
    r.tolerance = f.model == FlexureModel::kAuto ? f.tolerance : 0.0;
    double worst = 0.0;
    r.unmapped_points = 0;
    for (const FlexureTipLoad& load : r.loads) {
      const double e = mapped_flexure_error(r.model, r.elements, load);
      r.mapped_error.push_back(e);
      if (std::isnan(e)) {
        ++r.unmapped_points;
      } else {
        worst = std::max(worst, e);
      }
    }
    r.expected_error_per_length =
        r.unmapped_points > 0 ? std::numeric_limits<double>::quiet_NaN() : worst;
    if (options.measure_flexure_errors) {
      double largest = 0.0;
      bool all = !r.loads.empty();
      for (std::size_t k = 0; k < r.loads.size(); ++k) {
        const double e = measured_tip_error(r.loads[k], r.tips[k]);
        r.measured_error.push_back(e);
        if (std::isnan(e)) {
          all = false;
        } else {
          largest = std::max(largest, e);
        }
      }
      r.measured_error_per_length = all ? largest : std::numeric_limits<double>::quiet_NaN();
    }
    const std::size_t points = r.loads.size();
    const std::string mapped =
        r.model == FlexureModel::kExact ? std::string("expected error 0")
        : r.unmapped_points > 0
            ? fmt::format(
                  "no mapped error at {} of {} points (a load off the model ladder's map, or a "
                  "model the map does not describe)",
                  r.unmapped_points,
                  points)
            : fmt::format(
                  "its mapped tip error at the loads it carries is at most {:.2g} l over "
                  "the {} points (data/ladder_auto_error_map*.csv)",
                  worst,
                  points);
    if (f.model != FlexureModel::kAuto) {
      r.reason = fmt::format("{} as requested; {}", rung_title(r.model, r.elements), mapped);
      if (r.model == FlexureModel::kPrbm) {
        r.reason += " (Howell's average constants are not the map's 1R model)";
      }
    } else if (r.model == FlexureModel::kExact) {
      r.reason = fmt::format(
          "auto (tolerance {:.2g} of its length): the exact elastica, as no cheaper model of the "
          "ladder is within it at every point: {}",
          f.tolerance,
          joined(passed[i]));
    } else {
      r.reason = fmt::format(
          "auto (tolerance {:.2g} of its length): {}, the cheapest model of the ladder within it: "
          "{}{}",
          f.tolerance,
          rung_title(r.model, 6),
          mapped,
          passed[i].empty() ? std::string() : "; cheaper, but not within it: " + joined(passed[i]));
    }
  }
  // A CBCM flexure: its elements' largest deflection against the BCM's stated range (|y| <= 0.1
  // of an element, Awtar et al.), from the tip loads and tips recorded (m0 = mu - Fx y + Fy x).
  for (std::size_t i = 0; i < F; ++i) {
    const FlexureModelReport& r = reports[i];
    if (r.model != FlexureModel::kCbcm) continue;
    const Flexure& f = mechanism.flexures[i];
    const Vec2 pa = mechanism.point(f.a), pb = mechanism.point(f.b);
    const double l = std::hypot(pb.x - pa.x, pb.y - pa.y);
    // 1/d = EI/(EA l^2) = t^2/(12 l^2) (rectangle).
    const double inverse_d = f.extensible ? f.thickness * f.thickness / (12.0 * l * l) : 0.0;
    double largest = 0.0;
    for (std::size_t k = 0; k < r.loads.size(); ++k) {
      const FlexureTipLoad& l = r.loads[k];
      const FlexureTip& t = r.tips[k];
      CbcmMarchResult march;
      if (cbcm_march(r.elements, inverse_d, l.mu - l.Fx * t.y + l.Fy * t.x, l.Fx, l.Fy, march)) {
        largest = std::max(largest, march.max_element_deflection);
      }
    }
    if (largest > bcm::kValidDeflection) {
      result.warn(WarningKind::kOther,
                  fmt::format("flexure '{}': an element of its CBCM ({} elements) deflects {:.3g} "
                              "of its length, past the BCM's stated range {} (Awtar et al.): use "
                              "more elements",
                              f.name,
                              r.elements,
                              largest,
                              bcm::kValidDeflection));
    }
    if (!result.converged()) {
      result.message += fmt::format(
          "; flexure '{}' is a CBCM of {} elements: too few elements can give the chain a fold "
          "the elastica does not have (docs/mechanisms.md \"The inclined bistable beam with the "
          "CBCM\"), more follow the elastica closer",
          f.name,
          r.elements);
    }
  }
  result.flexure_models = std::move(reports);
  return result;
}

}  // namespace flexure::mechanism::general
