#include "flexure/io/mechanism_stroke_shapes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_exact_geometry.h"
#include "flexure/solver/common/status.h"

namespace flexure::io {
namespace {

using mechanism::GeometryPoint;
using mechanism::MechanismGeometry;

// One part of the half mechanism: a flexure (pivot 1..3) or a rigid link piece (0), with its rest
// x where it starts (parts are chained in that order, ground to slider).
struct Part {
  int pivot = 0;
  double rest_start_x = 0.0;
  std::vector<GeometryPoint> rest, deformed;
};

std::vector<Part> parts(const MechanismGeometry& g) {
  std::vector<Part> out;
  for (const mechanism::FlexureGeometry& f : g.flexures) {
    Part p{f.pivot, f.rest_start.x, {}, f.stroke_end_exact};
    // The rest stations at the same fractions of the length as the bent ones (equal spacing).
    const std::size_t n = f.stroke_end_exact.size();
    for (std::size_t k = 0; k < n; ++k) {
      const double t = n > 1 ? static_cast<double>(k) / static_cast<double>(n - 1) : 0.0;
      p.rest.push_back({f.rest_start.x + t * (f.rest_end.x - f.rest_start.x),
                        f.rest_start.y + t * (f.rest_end.y - f.rest_start.y)});
    }
    out.push_back(std::move(p));
  }
  for (const mechanism::RigidLinkGeometry& l : g.links) {
    out.push_back(
        {0, l.rest_start.x, {l.rest_start, l.rest_end}, {l.exact_end_start, l.exact_end_end}});
  }
  std::stable_sort(out.begin(), out.end(), [](const Part& a, const Part& b) {
    return a.rest_start_x < b.rest_start_x;
  });
  return out;
}

}  // namespace

int write_stroke_shapes(Hdf5Group& root, const mechanism::MechanismAnalysis& a, int samples) {
  if (!a.has_exact) return 0;
  std::vector<double> x, y, rest_x, rest_y, displacement;
  std::vector<int> part, index;
  std::size_t stations = 0;
  const std::vector<double>& rows = a.prbm.displacement;
  for (const mechanism::ExactPoint& p : a.exact.points) {
    if (!p.converged()) continue;
    // The row of /displacement with this Delta x (the exact stroke solves the same points).
    const auto row = std::find_if(rows.begin(), rows.end(), [&](double d) {
      return std::abs(d - p.displacement) <= 1e-12 * (a.design.r2 + a.design.r3);
    });
    if (row == rows.end()) continue;
    std::vector<Part> ps;
    try {
      ps = parts(mechanism::exact_geometry_at(a.design, p, samples));
    } catch (const InvalidInput& e) {
      // The shapes are an addition to the file: where they cannot be placed the file keeps its
      // curves and says why it has no /shapes.
      root.set_attribute("shapes_note", std::string("no /shapes: ") + e.what());
      return 0;
    } catch (const NoConvergence& e) {
      root.set_attribute("shapes_note", std::string("no /shapes: ") + e.what());
      return 0;
    }
    std::size_t count = 0;
    for (const Part& q : ps) {
      for (const GeometryPoint& v : q.deformed) {
        x.push_back(v.x);
        y.push_back(v.y);
      }
      count += q.deformed.size();
    }
    if (!index.empty() && count != stations) {
      throw std::logic_error("stroke shapes: the stations differ between stroke points");
    }
    if (index.empty()) {
      stations = count;
      for (const Part& q : ps) {
        for (const GeometryPoint& v : q.rest) {
          rest_x.push_back(v.x);
          rest_y.push_back(v.y);
          part.push_back(q.pivot);
        }
      }
    }
    index.push_back(static_cast<int>(row - rows.begin()));
    displacement.push_back(p.displacement);
  }
  if (index.empty()) return 0;
  const std::vector<hsize_t> dims = {static_cast<hsize_t>(index.size()),
                                     static_cast<hsize_t>(stations)};
  Hdf5Group g = root.create_group("shapes");
  g.set_attribute("model",
                  std::string("exact model (elastica, shooting): the stroke points it solved"));
  g.set_attribute("frame",
                  std::string("PRB pivot 1 at the origin, +x along the slider axis, y up "
                              "(docs/mechanisms.md); half mechanism, ground to slider"));
  g.write_dataset("displacement",
                  std::span<const double>(displacement),
                  "m",
                  "slider displacement Delta x of each stored shape (rows of /displacement)");
  g.write_dataset(
      "point_index", std::span<const int>(index), "1", "row of /displacement of each shape");
  g.write_dataset("x",
                  std::span<const double>(x),
                  dims,
                  "m",
                  "x of the deformed centreline [stroke point, station], ground to slider");
  g.write_dataset("y",
                  std::span<const double>(y),
                  dims,
                  "m",
                  "y of the deformed centreline [stroke point, station], ground to slider");
  g.write_dataset("rest_x", std::span<const double>(rest_x), "m", "x of each station at rest");
  g.write_dataset("rest_y", std::span<const double>(rest_y), "m", "y of each station at rest");
  g.write_dataset("part",
                  std::span<const int>(part),
                  "1",
                  "the flexure of each station: its PRB pivot 1..3; 0 a rigid link's end");
  return static_cast<int>(index.size());
}

}  // namespace flexure::io
