#pragma once
// The chained BCM's discretised segment (ladder_models.h): the chain in the flexible segment's
// units, the N elements' BCM relations as a residual, and the displacement control of one tip
// coordinate (cbcm_path.h). Internal to elements/ (Eigen types; not installed).
#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "flexure/elements/ladder_models.h"
#include "flexure/solver/chain_model/segment_chain.h"

namespace flexure::detail::cbcm {

struct PointLoad {
  double Fx = 0.0, Fy = 0.0, M = 0.0;
};

// The chain in the flexible segment's units (length L = 1, EI = 1): what the residual needs.
struct Prepared {
  double L = 1.0, EI = 1.0;
  double EA = std::numeric_limits<double>::infinity();   // the segment's (docs/extensible.md)
  double GAs = std::numeric_limits<double>::infinity();  // not modelled: the BCM is shear-rigid
  ChainPose root;                       // the segment's root (placed by the rigid links before it)
  std::vector<RigidSegment> tip_links;  // after the segment, lengths per L
  // Loads on the distal part: [0] at the segment's tip, [i] at the far end of tip link i-1 (the
  // last carries the chain's tip load); per EI/L^2 and EI/L.
  std::vector<PointLoad> distal_loads;
  // Loads on the clamped part before the segment (they pass to the clamp): position per L, load.
  std::vector<std::pair<ChainPose, PointLoad>> root_loads;
  PrescribedMask mask;
  ChainPose target;    // the prescribed tip at full load, per L
  ChainPose unloaded;  // the unloaded tip, per L
  int prescribed = 0;
  double load_scale = 1.0;  // max(1, |loads|, |tip motion|): the residual's scale
  // Displacement control (cbcm_path.h): the moved tip coordinate (0 x, 1 y, 2 theta; -1 none), and
  // whether the end condition prescribes it (else only the control does: in the loading stage its
  // reaction is held at 0, the coordinate free).
  int controlled = -1;
  bool controlled_by_end = false;
};

// The state of the discretised segment for unknowns z at load factor lambda.
struct Evaluation {
  std::vector<ChainPose> nodes;  // N + 1 element nodes (node 0 = the segment's root)
  std::vector<ChainPose> links;  // the far ends of the tip links
  double Fx = 0.0, Fy = 0.0;     // force on the distal part (reactions included)
  double Rx = 0.0, Ry = 0.0, Rm = 0.0;
  double moment_about_origin = 0.0;  // of the distal loads (reactions included)
  ChainPose tip;
};

// What the clamp holds and the chain's tip load at load factor lambda, per EI/L^2 and EI/L: the
// clamp holds the distal loads (reactions included) and the loads on the links before the segment
// (its reaction is the negative); the tip load is the given load plus the end's reactions.
struct EndLoads {
  PointLoad clamp, tip;
};
inline EndLoads end_loads(const Prepared& p, const Evaluation& e, double lambda) {
  EndLoads out;
  out.clamp = {e.Fx, e.Fy, e.moment_about_origin};
  for (const auto& [at, l] : p.root_loads) {
    out.clamp.Fx += lambda * l.Fx;
    out.clamp.Fy += lambda * l.Fy;
    out.clamp.M += lambda * (l.M + at.x * l.Fy - at.y * l.Fx);
  }
  const PointLoad& given = p.distal_loads.back();
  out.tip = {lambda * given.Fx + e.Rx, lambda * given.Fy + e.Ry, lambda * given.M + e.Rm};
  return out;
}

class Discretisation {
 public:
  Discretisation(const Prepared& prepared, int elements, double inverse_d)
      : p_(prepared), n_(elements), h_(1.0 / elements) {
    set_inverse_axial_stiffness(inverse_d);
  }
  // 1/d of the whole segment (0: inextensible); each element's is N^2/d.
  void set_inverse_axial_stiffness(double inverse_d) { inverse_de_ = inverse_d * n_ * n_; }

  int size() const { return 2 * n_ + p_.prescribed; }

  // The moving stage of displacement control: the loads and the other prescribed coordinates at
  // their full values, the controlled coordinate at start + lambda (end - start) (per L, or rad).
  void set_moving(double start, double end) {
    moving_ = true;
    control_start_ = start;
    control_end_ = end;
  }

  void evaluate(const Eigen::VectorXd& z, double lambda, Evaluation& e) const {
    int index = 2 * n_;
    e.Rx = p_.mask.x ? z[index++] : 0.0;
    e.Ry = p_.mask.y ? z[index++] : 0.0;
    e.Rm = p_.mask.theta ? z[index++] : 0.0;
    e.Fx = e.Rx;
    e.Fy = e.Ry;
    for (const PointLoad& l : p_.distal_loads) {
      e.Fx += lambda * l.Fx;
      e.Fy += lambda * l.Fy;
    }
    e.nodes.resize(static_cast<std::size_t>(n_ + 1));
    ChainPose at = p_.root;
    e.nodes[0] = at;
    for (int j = 0; j < n_; ++j) {
      const double c = std::cos(at.theta), s = std::sin(at.theta);
      const double y = z[2 * j], theta = z[2 * j + 1];
      const double p_hat = (e.Fx * c + e.Fy * s) * h_ * h_;
      const double x = bcm::axial_displacement(y, theta, p_hat, inverse_de_);
      at.x += h_ * ((1.0 + x) * c - y * s);
      at.y += h_ * ((1.0 + x) * s + y * c);
      at.theta += theta;
      e.nodes[static_cast<std::size_t>(j + 1)] = at;
    }
    const auto moment = [](const ChainPose& where, double Fx, double Fy, double M) {
      return M + where.x * Fy - where.y * Fx;
    };
    const PointLoad& first = p_.distal_loads[0];
    e.moment_about_origin = lambda * moment(at, first.Fx, first.Fy, first.M);
    e.links.clear();
    for (std::size_t i = 0; i < p_.tip_links.size(); ++i) {
      const RigidSegment& link = p_.tip_links[i];
      at.theta += link.angle_offset;
      at.x += link.length * std::cos(at.theta);
      at.y += link.length * std::sin(at.theta);
      e.links.push_back(at);
      const PointLoad& l = p_.distal_loads[i + 1];
      e.moment_about_origin += lambda * moment(at, l.Fx, l.Fy, l.M);
    }
    e.tip = at;
    e.moment_about_origin += moment(at, e.Rx, e.Ry, e.Rm);
  }

  // The BCM relations of every element (per EI/L^2 and EI/L) and the prescribed coordinates.
  void residual(const Eigen::VectorXd& z, double lambda, Evaluation& e, Eigen::VectorXd& r) const {
    const double path_lambda = lambda;
    if (moving_) lambda = 1.0;
    evaluate(z, lambda, e);
    r.resize(size());
    for (int j = 0; j < n_; ++j) {
      const ChainPose& root = e.nodes[static_cast<std::size_t>(j)];
      const ChainPose& tip = e.nodes[static_cast<std::size_t>(j + 1)];
      const double c = std::cos(root.theta), s = std::sin(root.theta);
      const double p_hat = (e.Fx * c + e.Fy * s) * h_ * h_;
      const double f_hat = (-e.Fx * s + e.Fy * c) * h_ * h_;
      // The distal loads' moment about the element's tip node.
      const double m_hat = (e.moment_about_origin - (tip.x * e.Fy - tip.y * e.Fx)) * h_;
      const bcm::Symmetric2 K = bcm::stiffness(p_hat);
      const double y = z[2 * j], theta = z[2 * j + 1];
      r[2 * j] = (K.a11 * y + K.a12 * theta - f_hat) / (h_ * h_);
      r[2 * j + 1] = (K.a12 * y + K.a22 * theta - m_hat) / h_;
    }
    int index = 2 * n_;
    const auto target = [&](double unloaded, double prescribed) {
      return unloaded + lambda * (prescribed - unloaded);
    };
    const double tip[3] = {e.tip.x, e.tip.y, e.tip.theta};
    const double reaction[3] = {e.Rx, e.Ry, e.Rm};
    const double unloaded[3] = {p_.unloaded.x, p_.unloaded.y, p_.unloaded.theta};
    const double prescribed[3] = {p_.target.x, p_.target.y, p_.target.theta};
    const bool masked[3] = {p_.mask.x, p_.mask.y, p_.mask.theta};
    for (int c = 0; c < 3; ++c) {
      if (!masked[c]) continue;
      if (c != p_.controlled) {
        r[index++] = tip[c] - target(unloaded[c], prescribed[c]);
      } else if (moving_) {
        r[index++] = tip[c] - (control_start_ + path_lambda * (control_end_ - control_start_));
      } else if (p_.controlled_by_end) {
        r[index++] = tip[c] - target(unloaded[c], prescribed[c]);
      } else {
        r[index++] = reaction[c];  // loading stage: the coordinate is free
      }
    }
  }

  int elements() const { return n_; }

 private:
  const Prepared& p_;
  int n_;
  double h_;
  double inverse_de_;  // 1/d of one element: N^2/d
  bool moving_ = false;
  double control_start_ = 0.0, control_end_ = 0.0;
};

// The chain in the flexible segment's units; throws InvalidInput naming `model` for a chain outside
// the model's class (ladder_models.h). `controlled` (0 x, 1 y, 2 theta; -1 none): a tip coordinate
// moved by displacement control, given an unknown reaction even where the end leaves it free.
Prepared prepare(const SegmentChain& chain, const std::string& model, int controlled = -1);

// The segment's axial stiffness d = EA L^2/EI (12 (L/t)^2 for a rectangle): its own EA, else the
// slenderness option's, else infinity (the inextensible elastica).
double axial_stiffness(const Prepared& p, double slenderness, const std::string& model);

}  // namespace flexure::detail::cbcm
