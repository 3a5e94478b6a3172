#include "flexure/io/csv_table.h"

#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/output_path.h"

namespace flexure::io {
namespace {

std::string quoted(const std::string& field) {
  if (field.find_first_of(",\"\n\r") == std::string::npos) return field;
  std::string out = "\"";
  for (char c : field) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

// An hid_t closed when it goes out of scope.
class Id {
 public:
  Id(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
    if (id_ < 0) throw Hdf5Error(what);
  }
  ~Id() {
    if (id_ >= 0) close_(id_);
  }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  hid_t get() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

struct DatasetInfo {
  std::string name;
  std::vector<hsize_t> shape;
  bool text = false;
};

herr_t visit_dataset(hid_t, const char* name, const H5O_info_t* info, void* data) {
  if (info->type == H5O_TYPE_DATASET) {
    static_cast<std::vector<std::string>*>(data)->emplace_back(name);
  }
  return 0;
}

DatasetInfo describe(hid_t file, const std::string& name, const std::string& where) {
  const Id set(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, where + ": no dataset " + name);
  const Id space(H5Dget_space(set.get()), H5Sclose, where + ": " + name + ": bad dataspace");
  const int rank = H5Sget_simple_extent_ndims(space.get());
  DatasetInfo info{name, std::vector<hsize_t>(static_cast<std::size_t>(std::max(rank, 0))), false};
  if (rank > 0) H5Sget_simple_extent_dims(space.get(), info.shape.data(), nullptr);
  const Id type(H5Dget_type(set.get()), H5Tclose, where + ": " + name + ": bad type");
  info.text = H5Tget_class(type.get()) == H5T_STRING;
  return info;
}

// The string attribute `attribute` of object `object` ("" when it has none).
std::string string_attribute(hid_t object, const std::string& name, const char* attribute) {
  if (H5Aexists(object, attribute) <= 0) return "";
  const Id attr(H5Aopen(object, attribute, H5P_DEFAULT), H5Aclose, name + ": " + attribute);
  const Id type(H5Aget_type(attr.get()), H5Tclose, name + ": " + attribute + " type");
  if (H5Tget_class(type.get()) != H5T_STRING) return "";
  if (H5Tis_variable_str(type.get()) > 0) {
    char* value = nullptr;
    const Id mem(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
    H5Tset_size(mem.get(), H5T_VARIABLE);
    H5Tset_cset(mem.get(), H5Tget_cset(type.get()));
    if (H5Aread(attr.get(), mem.get(), &value) < 0 || value == nullptr) return "";
    std::string out(value);
    H5free_memory(value);
    return out;
  }
  std::string out(H5Tget_size(type.get()), '\0');
  H5Aread(attr.get(), type.get(), out.data());
  return out.substr(0, out.find('\0'));
}

std::string units_of(hid_t file, const std::string& name) {
  const Id set(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
  const std::string units = string_attribute(set.get(), name, "units");
  return units.empty() ? "1" : units;
}

std::vector<double> read_numbers(hid_t file, const std::string& name) {
  const Id set(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
  const Id space(H5Dget_space(set.get()), H5Sclose, name + ": bad dataspace");
  std::vector<double> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())));
  if (!values.empty() &&
      H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
    throw Hdf5Error(name + ": read failed");
  }
  return values;
}

std::vector<std::string> read_texts(hid_t file, const std::string& name) {
  const Id set(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
  const Id space(H5Dget_space(set.get()), H5Sclose, name + ": bad dataspace");
  const Id type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  std::vector<char*> raw(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())));
  if (!raw.empty() &&
      H5Dread(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data()) < 0) {
    throw Hdf5Error(name + ": read failed");
  }
  std::vector<std::string> out;
  for (char* s : raw) {
    out.emplace_back(s != nullptr ? s : "");
    if (s != nullptr) H5free_memory(s);
  }
  return out;
}

bool skipped(const std::string& name, const std::vector<std::string>& skip) {
  return std::any_of(skip.begin(), skip.end(), [&](const std::string& group) {
    return name == group || name.rfind(group + "/", 0) == 0;
  });
}

}  // namespace

std::string force_unit(const std::string& force_of) {
  if (force_of == "one half" || force_of == "half") return "N (half)";
  if (force_of == "whole symmetric mechanism" || force_of == "whole") return "N (whole)";
  throw std::invalid_argument("force_unit: unknown force_of '" + force_of + "'");
}

void mark_force_columns(std::vector<CsvColumn>& columns, const std::string& force_of) {
  const std::string unit = force_unit(force_of);
  for (CsvColumn& c : columns) {
    if (c.unit == "N") c.unit = unit;
  }
}

std::string csv_text(const std::vector<CsvColumn>& columns) {
  const std::size_t rows = columns.empty() ? 0 : columns.front().size();
  std::string out;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c].size() != rows) {
      throw std::invalid_argument(fmt::format(
          "CSV column {} has {} rows, the first {}", columns[c].name, columns[c].size(), rows));
    }
    if (c > 0) out += ',';
    out += quoted(fmt::format("{} [{}]", columns[c].name, columns[c].unit));
  }
  out += "\n";
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c > 0) out += ",";
      if (columns[c].is_text()) {
        out += quoted(columns[c].texts[r]);
      } else if (std::isfinite(columns[c].numbers[r])) {
        out += fmt::format("{:.17g}", columns[c].numbers[r]);
      }  // NaN: an empty field
    }
    out += "\n";
  }
  return out;
}

void write_csv(const std::string& path,
               const std::vector<CsvColumn>& columns,
               const std::string& option) {
  write_text_file(path, csv_text(columns), option);
}

std::vector<CsvColumn> csv_columns_from_hdf5(const std::string& hdf5_path,
                                             const std::vector<std::string>& axes,
                                             const std::vector<std::string>& skip) {
  const Id file(H5Fopen(hdf5_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT),
                H5Fclose,
                hdf5_path + ": cannot open as HDF5");
  std::vector<hsize_t> grid;
  std::vector<CsvColumn> axis_columns;
  for (const std::string& axis : axes) {
    const DatasetInfo info = describe(file.get(), axis, hdf5_path);
    if (info.shape.size() != 1) throw Hdf5Error(hdf5_path + ": axis " + axis + " is not 1-D");
    grid.push_back(info.shape[0]);
    CsvColumn column{axis, units_of(file.get(), axis), {}, {}};
    if (info.text) {
      column.unit = "text";
      column.texts = read_texts(file.get(), axis);
    } else {
      column.numbers = read_numbers(file.get(), axis);
    }
    axis_columns.push_back(std::move(column));
  }
  std::size_t rows = 1;
  for (hsize_t n : grid) rows *= static_cast<std::size_t>(n);

  std::vector<CsvColumn> columns;
  // The axes, expanded over the grid: axis k's value at row r is axis_k[index_k(r)].
  std::size_t stride = rows;
  for (std::size_t k = 0; k < axis_columns.size(); ++k) {
    stride /= std::max<std::size_t>(grid[k], 1);
    CsvColumn expanded{axis_columns[k].name, axis_columns[k].unit, {}, {}};
    for (std::size_t r = 0; r < rows; ++r) {
      const std::size_t i = (r / stride) % grid[k];
      if (expanded.is_text()) {
        expanded.texts.push_back(axis_columns[k].texts[i]);
      } else {
        expanded.numbers.push_back(axis_columns[k].numbers[i]);
      }
    }
    columns.push_back(std::move(expanded));
  }
  std::vector<std::string> names;
  if (H5Ovisit2(file.get(), H5_INDEX_NAME, H5_ITER_INC, visit_dataset, &names, H5O_INFO_BASIC) <
      0) {
    throw Hdf5Error(hdf5_path + ": cannot list the datasets");
  }
  for (const std::string& name : names) {
    if (skipped(name, skip) || std::find(axes.begin(), axes.end(), name) != axes.end()) continue;
    const DatasetInfo info = describe(file.get(), name, hdf5_path);
    if (info.shape != grid) continue;
    CsvColumn column{name, units_of(file.get(), name), {}, {}};
    if (info.text) {
      column.unit = "text";
      column.texts = read_texts(file.get(), name);
    } else {
      column.numbers = read_numbers(file.get(), name);
    }
    columns.push_back(std::move(column));
  }
  const std::string force_of = string_attribute(file.get(), hdf5_path, "force_of");
  if (force_of == "one half" || force_of == "whole symmetric mechanism") {
    mark_force_columns(columns, force_of);
  }
  return columns;
}

}  // namespace flexure::io
