#include "flexure/io/shapes_xdmf.h"

#include <fmt/format.h>

#include "flexure/solver/common/status.h"

namespace flexure::io {
namespace {

// A row of a [solutions, stations] dataset as a 1 x stations hyperslab (XDMF 3 HyperSlab: the
// first child gives start, stride and count per dimension).
std::string row(const ShapesXdmf& s, int i, const std::string& name, const std::string& indent) {
  return fmt::format(
      "{0}<DataItem ItemType=\"HyperSlab\" Dimensions=\"1 {1}\" Type=\"HyperSlab\">\n"
      "{0}  <DataItem Dimensions=\"3 2\" NumberType=\"Int\" Format=\"XML\">{2} 0 1 1 1 {1}"
      "</DataItem>\n"
      "{0}  <DataItem Dimensions=\"{3} {1}\" NumberType=\"Float\" Precision=\"8\" "
      "Format=\"HDF\">{4}:{5}/{6}</DataItem>\n"
      "{0}</DataItem>\n",
      indent,
      s.stations,
      i,
      s.solutions,
      s.h5_file_name,
      s.group,
      name);
}

}  // namespace

std::string shapes_xdmf(const ShapesXdmf& s) {
  if (s.solutions < 1 || s.stations < 1) {
    throw InvalidInput(
        fmt::format("an XDMF file of shapes needs >= 1 solution and station (got {} and {})",
                    s.solutions,
                    s.stations));
  }
  if (!s.times.empty() && static_cast<int>(s.times.size()) != s.solutions) {
    throw InvalidInput("an XDMF file of shapes needs one time per solution");
  }
  std::string connectivity;
  for (int k = 0; k < s.stations; ++k) connectivity += fmt::format("{}{}", k ? " " : "", k);
  std::string out =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<Xdmf xmlns:xi=\"http://www.w3.org/2001/XInclude\" Version=\"3.0\">\n"
      "  <Domain>\n"
      "    <Grid Name=\"shapes\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (int i = 0; i < s.solutions; ++i) {
    out += fmt::format("      <Grid Name=\"solution {}\" GridType=\"Uniform\">\n", i);
    out += fmt::format("        <Time Value=\"{:.17g}\"/>\n",
                       s.times.empty() ? static_cast<double>(i) : s.times[i]);
    out += fmt::format(
        "        <Topology TopologyType=\"Polyline\" NumberOfElements=\"1\" "
        "NodesPerElement=\"{0}\">\n"
        "          <DataItem Dimensions=\"1 {0}\" NumberType=\"Int\" Format=\"XML\">{1}"
        "</DataItem>\n"
        "        </Topology>\n",
        s.stations,
        connectivity);
    out += "        <Geometry GeometryType=\"XY\">\n";
    out += fmt::format(
        "          <DataItem ItemType=\"Function\" Function=\"JOIN($0, $1)\" "
        "Dimensions=\"{} 2\">\n",
        s.stations);
    out += row(s, i, "x", "            ");
    out += row(s, i, "y", "            ");
    out += "          </DataItem>\n        </Geometry>\n";
    if (!s.station_field.empty()) {
      out += fmt::format(
          "        <Attribute Name=\"{0}\" AttributeType=\"Scalar\" Center=\"Node\">\n"
          "          <DataItem Dimensions=\"{1}\" NumberType=\"Float\" Precision=\"8\" "
          "Format=\"HDF\">{2}:{3}/{0}</DataItem>\n"
          "        </Attribute>\n",
          s.station_field,
          s.stations,
          s.h5_file_name,
          s.group);
    }
    for (const std::string& f : s.fields) {
      out += fmt::format(
          "        <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Node\">\n", f);
      out += row(s, i, f, "          ");
      out += "        </Attribute>\n";
    }
    out += "      </Grid>\n";
  }
  out += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return out;
}

std::string xdmf_path_for(const std::string& h5_path) {
  for (const char* ext : {".h5", ".hdf5", ".H5"}) {
    const std::string e = ext;
    if (h5_path.size() > e.size() && h5_path.compare(h5_path.size() - e.size(), e.size(), e) == 0) {
      return h5_path.substr(0, h5_path.size() - e.size()) + ".xdmf";
    }
  }
  return h5_path + ".xdmf";
}

}  // namespace flexure::io
