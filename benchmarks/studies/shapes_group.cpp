#include "flexure/benchmarks/studies/shapes_group.h"

#include <filesystem>

#include "flexure/io/platform/output_path.h"
#include "flexure/io/shapes_xdmf.h"

namespace flexure {

void write_shapes_group(io::Hdf5Group& root, const ShapesView& v) {
  io::Hdf5Group shapes = root.create_group("shapes");
  const std::vector<hsize_t> dims = {static_cast<hsize_t>(v.rows),
                                     static_cast<hsize_t>(v.shape_points)};
  const std::string at = " [" + v.row_name + ", shape point]";
  shapes.write_dataset(
      "s", v.s, v.length_unit, "arc length from the clamp of each shape column" + v.scaled);
  shapes.write_dataset("x", v.x, dims, v.length_unit, "x of the shape" + at + v.scaled);
  shapes.write_dataset("y", v.y, dims, v.length_unit, "y of the shape" + at + v.scaled);
  shapes.write_dataset("theta", v.theta, dims, "rad", "tangent angle" + at);
  shapes.write_dataset("moment",
                       v.moment,
                       dims,
                       v.moment_unit,
                       "bending moment m = EI (theta' - kappa0)" + at +
                           ", counter-clockwise on the part nearer the clamp" + v.scaled);
  if (!v.axial.empty()) {
    shapes.write_dataset("axial_force",
                         v.axial,
                         dims,
                         v.force_unit,
                         "internal force N . t (tension positive)" + at + v.scaled);
    shapes.write_dataset(
        "shear_force",
        v.shear,
        dims,
        v.force_unit,
        "internal force N . n, n left of the tangent (dm/ds = -V)" + at + v.scaled);
  }
  if (!v.stress_pos.empty()) {
    shapes.write_dataset("stress_pos_fibre",
                         v.stress_pos,
                         dims,
                         "Pa",
                         "stress N/A - m c/I at the fibre h/2 along the normal left of the "
                         "tangent" +
                             at);
    shapes.write_dataset("stress_neg_fibre",
                         v.stress_neg,
                         dims,
                         "Pa",
                         "stress N/A + m c/I at the fibre h/2 along the normal right of the "
                         "tangent" +
                             at);
  }
}

std::string write_shapes_xdmf(const std::string& h5_path,
                              const ShapesView& v,
                              const std::vector<double>& times) {
  if (v.shape_points <= 0 || v.rows == 0) return {};
  io::ShapesXdmf x;
  x.h5_file_name = std::filesystem::path(h5_path).filename().string();
  x.group = "/shapes";
  x.solutions = static_cast<int>(v.rows);
  x.stations = v.shape_points;
  x.times = times;
  x.fields = {"theta", "moment"};  // the [row, shape point] datasets of write_shapes_group
  if (!v.axial.empty()) {
    x.fields.push_back("axial_force");
    x.fields.push_back("shear_force");
  }
  if (!v.stress_pos.empty()) {
    x.fields.push_back("stress_pos_fibre");
    x.fields.push_back("stress_neg_fibre");
  }
  // Constructed, not assigned: GCC 12 warns falsely (-Wrestrict) on assigning a one-character
  // literal.
  x.station_field = std::string(1, 's');
  const std::string path = io::xdmf_path_for(h5_path);
  io::write_text_file(path, io::shapes_xdmf(x), "--out (XDMF sidecar)");
  return path;
}

}  // namespace flexure
