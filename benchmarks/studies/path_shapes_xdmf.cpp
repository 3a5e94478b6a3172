#include "flexure/benchmarks/studies/path_shapes_xdmf.h"

#include "flexure/benchmarks/studies/shapes_group.h"

namespace flexure {

std::string write_path_shapes_xdmf(const std::string& h5_path, const PathTable& t) {
  if (t.shape_points <= 0 || t.size() == 0) return {};
  return write_shapes_xdmf(h5_path, path_shapes_view(t), t.load_factor);
}

}  // namespace flexure
