#include "flexure/benchmarks/studies/path_shapes_xdmf.h"

#include <filesystem>

#include "flexure/io/output_path.h"
#include "flexure/io/shapes_xdmf.h"

namespace flexure {

std::string write_path_shapes_xdmf(const std::string& h5_path, const PathTable& t) {
  if (t.shape_points <= 0 || t.size() == 0) return {};
  io::ShapesXdmf x;
  x.h5_file_name = std::filesystem::path(h5_path).filename().string();
  x.group = "/shapes";
  x.solutions = static_cast<int>(t.size());
  x.stations = t.shape_points;
  x.times = t.load_factor;
  x.fields = {"theta", "moment"};  // the [path point, shape point] datasets of write_path_file
  if (!t.shape_axial.empty()) {
    x.fields.push_back("axial_force");
    x.fields.push_back("shear_force");
  }
  if (!t.shape_stress_pos.empty()) {
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
