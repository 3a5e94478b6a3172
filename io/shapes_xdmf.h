#pragma once
// The XDMF 3 sidecar of an HDF5 file of shapes (issue 29 item 6): FILE.xdmf next to FILE.h5 that
// ParaView (Xdmf3 reader) opens as it is. One temporal collection, one grid per stored solution
// (a path point): a polyline over the shape's stations s, its XY geometry joined from hyperslab
// rows of the [solutions, stations] datasets x and y, and every other [solutions, stations]
// dataset as a node attribute. The heavy data stay in the HDF5 file, referenced as
// "FILE.h5:/group/name" (the file name relative to the sidecar, which sits next to it).
#include <string>
#include <vector>

namespace flexure::io {

struct ShapesXdmf {
  std::string h5_file_name;         // as referenced: the HDF5 file's name without directories
  std::string group;                // "/shapes"
  int solutions = 0;                // rows of the datasets
  int stations = 0;                 // columns: the shape points along s
  std::vector<double> times;        // one per solution (the path's load factor), for the time axis
  std::vector<std::string> fields;  // [solutions, stations] datasets besides x and y
  std::string station_field;        // a 1-D [stations] dataset (the arc length s), may be empty
};

// The XDMF text (XML) of `shapes`. Throws InvalidInput for solutions or stations < 1 or a times
// vector of another length.
std::string shapes_xdmf(const ShapesXdmf& shapes);

// The sidecar's path for an HDF5 path: "dir/run.h5" -> "dir/run.xdmf" (".xdmf" appended to a
// name without the .h5/.hdf5 extension).
std::string xdmf_path_for(const std::string& h5_path);

}  // namespace flexure::io
