// ================================================================================================
// flexure tutorial, step 1: a steel strip with a rigid link, two ways.
//
// The program is the document (README.md beside it says what it prints). It builds a problem from
// the library's objects -- a cross-section, a material, a flexible segment, a rigid segment and a
// tip load, put together as a segment chain -- and solves it by two independent methods: the
// shooting method (the elastica integrated to 1e-12 and its end conditions met by Newton's method)
// and Howell's chain algorithm (the strip cut into short elements, Howell ch. 7). It prints both
// tips and their difference, and draws both deflected shapes into an SVG file.
//
// Build against the installed package (CMakeLists.txt); it links flexure::beam only.
// Run: ./step-1 [shapes.svg]      (default: step-1.svg in the working directory)
// ================================================================================================

// 1. Includes
//
// <flexure/beam.h> is the beam layer in one include: sections and materials, segment chains, the
// exact solvers with their Options and results. It links neither HDF5 nor toml++.
#include <flexure/beam.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

// 2. Writing an SVG plot
//
// Two polylines in one coordinate frame, with no plotting library: the SVG's y axis points down,
// so y is flipped; both shapes share one scale so that they overlay where the methods agree.
struct Curve {
  std::vector<flexure::ShapePoint> points;
  const char* colour;
  const char* label;
  const char* dash;  // SVG stroke-dasharray, "" for a solid line
};

// `length`: the undeformed chain's, drawn grey along +x from the clamp.
bool write_svg(const std::string& path, const std::vector<Curve>& curves, double length) {
  double x_min = 0.0, x_max = length, y_min = 0.0, y_max = 0.0;
  for (const Curve& c : curves) {
    for (const flexure::ShapePoint& p : c.points) {
      x_min = std::min(x_min, p.x);
      x_max = std::max(x_max, p.x);
      y_min = std::min(y_min, p.y);
      y_max = std::max(y_max, p.y);
    }
  }
  const double width = 640.0, height = 480.0, margin = 40.0;
  const double scale = std::min((width - 2 * margin) / std::max(x_max - x_min, 1e-12),
                                (height - 2 * margin) / std::max(y_max - y_min, 1e-12));
  auto px = [&](double x) { return margin + (x - x_min) * scale; };
  const double y_offset = 0.5 * (height - 2 * margin - (y_max - y_min) * scale);  // centred
  auto py = [&](double y) { return height - margin - y_offset - (y - y_min) * scale; };

  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<line x1=\"" << px(0.0) << "\" y1=\"" << py(y_min) << "\" x2=\"" << px(0.0) << "\" y2=\""
      << py(y_max) << "\" stroke=\"black\" stroke-width=\"4\"/>\n"  // the clamp
      << "<line x1=\"" << px(0.0) << "\" y1=\"" << py(0.0) << "\" x2=\"" << px(length) << "\" y2=\""
      << py(0.0) << "\" stroke=\"#999999\" stroke-width=\"1\"/>\n";  // undeformed
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const Curve& c = curves[k];
    out << "<polyline fill=\"none\" stroke=\"" << c.colour << "\" stroke-width=\"2\"";
    if (*c.dash != '\0') out << " stroke-dasharray=\"" << c.dash << '"';
    out << " points=\"";
    char xy[64];
    for (const flexure::ShapePoint& p : c.points) {
      std::snprintf(xy, sizeof xy, "%.2f,%.2f ", px(p.x), py(p.y));
      out << xy;
    }
    out << "\"/>\n"
        << "<text x=\"" << margin << "\" y=\"" << 20 + 16 * k << "\" fill=\"" << c.colour
        << "\" font-family=\"sans-serif\" font-size=\"14\">" << c.label << "</text>\n";
  }
  out << "</svg>\n";

  // Written whole or not at all: to a temporary file beside the target, then renamed.
  const std::string temporary = path + ".part";
  {
    std::ofstream file(temporary, std::ios::binary);
    file << out.str();
    if (!file.flush()) {
      std::remove(temporary.c_str());
      return false;
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    return false;
  }
  return true;
}

}  // namespace

int run(const std::string& svg_path) {
  // 3. The problem, built from objects
  //
  // A spring-steel strip 50 mm long, 10 mm wide and 0.5 mm thick, clamped at one end; a rigid
  // link 20 mm long is fixed to its free end (a stiff block, say), and a 3 N force acts at the
  // link's end perpendicular to the undeformed strip. Units are SI throughout (docs/units.md).
  //
  // Section::rectangle and Material validate their fields (a negative thickness throws
  // InvalidInput naming `Section::thickness`); flexural_rigidity gives E I = E b h^3/12.
  const flexure::Section strip = flexure::Section::rectangle(/*width=*/0.010, /*thickness=*/0.0005);
  flexure::Material steel;
  steel.E = 200e9;
  steel.nu = 0.3;
  steel.yield_strength = 1.4e9;  // spring steel
  const double EI = flexure::flexural_rigidity(strip, steel);

  // The chain lists its segments from the clamp to the tip. The tip is free (the default end
  // condition) and carries a dead load, fixed in direction as the strip bends.
  flexure::SegmentChain chain;
  chain.segments.push_back(flexure::FlexibleSegment(/*length=*/0.050, EI));
  chain.segments.push_back(flexure::RigidSegment{/*length=*/0.020, /*angle_offset=*/0.0});
  chain.tip_load.Fy = 3.0;  // N
  chain.validate();
  const double L = chain.total_length();

  std::printf("strip: L = 50 mm, b = 10 mm, h = 0.5 mm, E = 200 GPa: EI = %.6g N m^2\n", EI);
  std::printf("rigid link 20 mm, tip force Fy = 3 N: Fy L^2/EI = %.6f over the total length\n",
              chain.tip_load.Fy * L * L / EI);

  // 4. Solution 1: the shooting method
  //
  // The shooting solver integrates the elastica from the clamp with guessed root loads and
  // corrects them by Newton's method until the tip's conditions hold (docs/theory-shooting.md);
  // it crosses the rigid link exactly. Asking for shape points returns the deflected shape.
  flexure::ShootingSolver::Options shooting_options;
  shooting_options.shape_points = 201;
  const flexure::ShootingResult shot = flexure::ShootingSolver(shooting_options).solve(chain);
  if (!shot.converged()) {
    std::fprintf(stderr, "shooting: not converged: %s\n", shot.message.c_str());
    return 3;
  }

  // 5. Solution 2: Howell's chain algorithm
  //
  // The chain algorithm cuts the strip into 100 elements and converges Howell's passes over them
  // (Howell §7.2, with the corrections of docs/theory-chain.md). It is a discretisation: its tip
  // error falls like 1/N^3 (about 0.85/N^3 of the length at Fy L^2/EI = 10, docs/theory-chain.md
  // §3), so at N = 100 it should agree with the shooting method within 8.5e-7 of the length.
  flexure::ChainAlgorithmSolver::Options chain_options;
  chain_options.elements = 100;
  const flexure::ChainResult howell = flexure::ChainAlgorithmSolver(chain_options).solve(chain);
  if (!howell.converged()) {
    std::fprintf(stderr, "chain algorithm: not converged: %s\n", howell.message.c_str());
    return 3;
  }

  // 6. Comparing the two
  //
  // Both tips in metres and radians, and the difference of the positions in total lengths: the
  // quantity docs/theory-chain.md tabulates.
  std::printf("shooting:        tip x = %.12f m  y = %.12f m  theta = %.12f rad\n",
              shot.tip.x,
              shot.tip.y,
              shot.tip.theta);
  std::printf("chain algorithm: tip x = %.12f m  y = %.12f m  theta = %.12f rad  (%d elements)\n",
              howell.tip.x,
              howell.tip.y,
              howell.tip.theta,
              howell.elements);
  const double dx = std::abs(shot.tip.x - howell.tip.x);
  const double dy = std::abs(shot.tip.y - howell.tip.y);
  const double dtheta = std::abs(shot.tip.theta - howell.tip.theta);
  std::printf(
      "difference:      |dx| = %.3e m  |dy| = %.3e m  |dtheta| = %.3e rad\n", dx, dy, dtheta);
  std::printf("largest difference in total lengths (and rad): %.3e\n",
              std::max({dx / L, dy / L, dtheta}));

  // The stress at the clamp, from the root moment and the section modulus b h^2/6: what a
  // designer checks next (the strip must not yield).
  const double stress = std::abs(shot.reaction.M) / strip.section_modulus().value();
  std::printf("bending stress at the clamp: %.1f MPa, safety factor %.2f against yield\n",
              stress / 1e6,
              *steel.yield_strength / stress);

  // 7. Plotting both shapes
  //
  // The shooting method's 201 shape points and the chain algorithm's element nodes, overlaid.
  const bool written =
      write_svg(svg_path,
                {Curve{shot.shape, "#1f77b4", "shooting method (201 points)", ""},
                 Curve{howell.nodes, "#d62728", "chain algorithm (element nodes)", "6,4"}},
                L);
  if (!written) {
    std::fprintf(stderr, "could not write %s\n", svg_path.c_str());
    return 4;
  }
  std::printf("shapes written to %s\n", svg_path.c_str());
  return 0;
}

// 8. The main function
//
// Bad input (a negative length, a NaN load) throws flexure::InvalidInput with a message naming
// the field; a program reports it and exits with 2, as the `flexure` tool does (docs/cli.md).
int main(int argc, char** argv) {
  try {
    return run(argc > 1 ? argv[1] : "step-1.svg");
  } catch (const flexure::InvalidInput& e) {
    std::fprintf(stderr, "invalid input: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 4;
  }
}
