#include "flexure/solver/chain/chain_transfer.h"

#include <stdexcept>
#include <vector>

namespace flexure {

namespace {

// Arc length of every element node (node i > 0 is the far end of element i - 1).
std::vector<double> node_arc_lengths(const ChainDiscretisation& d) {
  std::vector<double> s(d.element_count() + 1, 0.0);
  for (int i = 0; i < d.element_count(); ++i) {
    s[i + 1] = d.elements[i].s_start + d.elements[i].length;
  }
  return s;
}

}  // namespace

ChainGeometry transfer_geometry(const ChainDiscretisation& from,
                                const ChainGeometry& from_geometry,
                                const ChainDiscretisation& to) {
  if (from.model_node.size() != to.model_node.size() ||
      static_cast<int>(from_geometry.theta.size()) != from.element_count() + 1) {
    throw std::logic_error("transfer_geometry: the discretisations differ in their chain");
  }
  const std::vector<double> s_from = node_arc_lengths(from);
  const std::vector<double> s_to = node_arc_lengths(to);
  ChainGeometry out;
  const int nodes = to.element_count() + 1;
  out.x.assign(nodes, 0.0);
  out.y.assign(nodes, 0.0);
  out.theta.assign(nodes, 0.0);
  auto copy = [&](int i, int k) {
    out.x[i] = from_geometry.x[k];
    out.y[i] = from_geometry.y[k];
    out.theta[i] = from_geometry.theta[k];
  };
  copy(0, 0);
  for (std::size_t j = 0; j + 1 < to.model_node.size(); ++j) {
    const int a = to.model_node[j], b = to.model_node[j + 1];
    const int c = from.model_node[j], d = from.model_node[j + 1];
    copy(a, c);
    copy(b, d);
    int k = c;  // coarse interval [k, k + 1] holding the current node
    for (int i = a + 1; i < b; ++i) {
      while (k + 1 < d && s_from[k + 1] < s_to[i]) ++k;
      const double h = s_from[k + 1] - s_from[k];
      const double t = h > 0.0 ? (s_to[i] - s_from[k]) / h : 0.0;
      out.x[i] = (1.0 - t) * from_geometry.x[k] + t * from_geometry.x[k + 1];
      out.y[i] = (1.0 - t) * from_geometry.y[k] + t * from_geometry.y[k + 1];
      out.theta[i] = (1.0 - t) * from_geometry.theta[k] + t * from_geometry.theta[k + 1];
    }
  }
  return out;
}

}  // namespace flexure
