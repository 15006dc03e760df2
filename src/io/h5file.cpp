// h5file.cpp: HDF5 C API calls behind the H5File wrapper.
#include "io/h5file.h"

#include <hdf5.h>

#include <algorithm>

#include "swarf/core/errors.h"

namespace swarf {
namespace {

void quiet_hdf5() {
  static bool done = false;
  if (!done) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    done = true;
  }
}

hid_t link_props() {
  hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  return lcpl;
}

}  // namespace

H5File::H5File(const std::string& path, Mode mode) : path_(path) {
  quiet_hdf5();
  if (mode == Mode::Create) {
    id_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (id_ < 0) throw OutputError("cannot create HDF5 file '" + path + "'");
  } else {
    id_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (id_ < 0) throw InputError("cannot open HDF5 file '" + path + "' (missing or not HDF5)");
  }
}

H5File::~H5File() {
  if (id_ >= 0) H5Fclose(static_cast<hid_t>(id_));
}

void H5File::close() {
  if (id_ < 0) return;
  const herr_t st = H5Fclose(static_cast<hid_t>(id_));
  id_ = -1;
  if (st < 0) throw OutputError("writing HDF5 file '" + path_ + "' failed when closing it (disk full?)");
}

static void write_any(hid_t file, const std::string& path, const std::string& name, hid_t type, const void* data,
                      std::size_t rows, std::size_t cols, hid_t memory_type = -1) {
  hsize_t dims[2] = {rows, cols};
  hid_t space = H5Screate_simple(cols == 1 ? 1 : 2, dims, nullptr);
  hid_t lcpl = link_props();
  hid_t set = H5Dcreate2(file, name.c_str(), type, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  herr_t st = set < 0 ? -1
              : rows * cols == 0
                  ? 0
                  : H5Dwrite(set, memory_type < 0 ? type : memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  if (set >= 0) H5Dclose(set);
  H5Pclose(lcpl);
  H5Sclose(space);
  if (st < 0) throw OutputError("cannot write dataset '" + name + "' to HDF5 file '" + path + "' (disk full?)");
}

void H5File::write(const std::string& name, const double* data, std::size_t rows, std::size_t cols) {
  write_any(id_, path_, name, H5T_NATIVE_DOUBLE, data, rows, cols);
}
void H5File::write(const std::string& name, const std::int64_t* data, std::size_t rows, std::size_t cols) {
  write_any(id_, path_, name, H5T_NATIVE_INT64, data, rows, cols);
}
void H5File::write(const std::string& name, const std::int32_t* data, std::size_t rows, std::size_t cols) {
  write_any(id_, path_, name, H5T_NATIVE_INT64, data, rows, cols, H5T_NATIVE_INT32);
}
void H5File::write(const std::string& name, const std::uint8_t* data, std::size_t rows) {
  write_any(id_, path_, name, H5T_NATIVE_UINT8, data, rows, 1);
}

void H5File::write_strips(const std::string& name, std::size_t rows, std::size_t cols, std::size_t strip,
                          const std::function<void(std::size_t, std::size_t, std::vector<double>&)>& fill) {
  const hid_t file = static_cast<hid_t>(id_);
  const int rank = cols == 1 ? 1 : 2;
  hsize_t dims[2] = {rows, cols};
  hid_t space = H5Screate_simple(rank, dims, nullptr);
  hid_t lcpl = link_props();
  hid_t set = H5Dcreate2(file, name.c_str(), H5T_NATIVE_DOUBLE, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  herr_t st = set < 0 ? -1 : 0;
  std::vector<double> values;
  strip = std::max<std::size_t>(strip, 1);
  const auto release = [&] {
    if (set >= 0) H5Dclose(set);
    H5Pclose(lcpl);
    H5Sclose(space);
  };
  try {
    for (std::size_t b = 0; st >= 0 && b < rows; b += strip) {
      const std::size_t e = std::min(rows, b + strip);
      fill(b, e, values);
      hsize_t start[2] = {b, 0}, count[2] = {e - b, cols};
      hid_t memory = H5Screate_simple(rank, count, nullptr);
      st = H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, count, nullptr);
      if (st >= 0) st = H5Dwrite(set, H5T_NATIVE_DOUBLE, memory, space, H5P_DEFAULT, values.data());
      H5Sclose(memory);
    }
  } catch (...) {  // (a field that cannot be computed: the handles go before the error does)
    release();
    throw;
  }
  release();
  if (st < 0) throw OutputError("cannot write dataset '" + name + "' to HDF5 file '" + path_ + "' (disk full?)");
}

// A fixed-length string attribute on the object 'obj'; false when HDF5 refuses it.
static bool string_attribute(hid_t obj, const std::string& name, const std::string& value) {
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.size() + 1);
  H5Tset_cset(type, H5T_CSET_UTF8);
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t attr = H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  herr_t st = attr >= 0 ? H5Awrite(attr, type, value.c_str()) : -1;
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
  return st >= 0;
}

void H5File::write_attribute(const std::string& name, const std::string& value) {
  if (!string_attribute(id_, name, value))
    throw OutputError("cannot write attribute '" + name + "' to '" + path_ + "'");
}

void H5File::write_strings(const std::string& name, const std::vector<std::string>& values) {
  std::vector<const char*> p;
  for (const auto& v : values) p.push_back(v.c_str());
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  write_any(id_, path_, name, type, p.data(), p.size(), 1);  // (throws after closing what it opened)
  H5Tclose(type);
}

void H5File::describe(const std::string& name, const std::string& unit, const std::string& description) {
  hid_t set = H5Dopen2(id_, name.c_str(), H5P_DEFAULT);
  const bool ok = set >= 0 && string_attribute(set, "unit", unit) && string_attribute(set, "description", description);
  if (set >= 0) H5Dclose(set);
  if (!ok) throw OutputError("cannot describe dataset '" + name + "' in '" + path_ + "'");
}

std::vector<std::string> H5File::datasets() const {
  std::vector<std::string> out;
  auto visit = [](hid_t, const char* name, const H5O_info_t* info, void* data) -> herr_t {
    if (info->type == H5O_TYPE_DATASET)
      static_cast<std::vector<std::string>*>(data)->push_back(std::string("/") + name);
    return 0;
  };
  H5Ovisit2(id_, H5_INDEX_NAME, H5_ITER_INC, visit, &out, H5O_INFO_BASIC);
  std::sort(out.begin(), out.end());
  return out;
}

std::string H5File::dataset_attribute(const std::string& name, const std::string& attribute) const {
  hid_t set = H5Dopen2(id_, name.c_str(), H5P_DEFAULT);
  if (set < 0) throw InputError("HDF5 file '" + path_ + "' has no dataset '" + name + "'");
  std::string out;
  if (H5Aexists(set, attribute.c_str()) > 0) {
    hid_t attr = H5Aopen(set, attribute.c_str(), H5P_DEFAULT);
    hid_t type = H5Aget_type(attr);
    out.assign(H5Tget_size(type), '\0');
    H5Aread(attr, type, out.data());
    H5Tclose(type);
    H5Aclose(attr);
    while (!out.empty() && out.back() == '\0') out.pop_back();
  }
  H5Dclose(set);
  return out;
}

// A double attribute on the object 'obj'; false when HDF5 refuses it.
static bool double_attribute(hid_t obj, const std::string& name, double value) {
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t attr = H5Acreate2(obj, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
  herr_t st = attr >= 0 ? H5Awrite(attr, H5T_NATIVE_DOUBLE, &value) : -1;
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  return st >= 0;
}

void H5File::write_attribute(const std::string& name, double value) {
  if (!double_attribute(id_, name, value))
    throw OutputError("cannot write attribute '" + name + "' to '" + path_ + "'");
}

void H5File::write_attribute(const std::string& object, const std::string& name, double value) {
  hid_t obj = H5Oopen(id_, object.c_str(), H5P_DEFAULT);
  const bool ok = obj >= 0 && double_attribute(obj, name, value);
  if (obj >= 0) H5Oclose(obj);
  if (!ok) throw OutputError("cannot write attribute '" + name + "' of '" + object + "' to '" + path_ + "'");
}

double H5File::read_double_attribute(const std::string& object, const std::string& name) const {
  hid_t obj = H5Oopen(id_, object.c_str(), H5P_DEFAULT);
  if (obj < 0) throw InputError("HDF5 file '" + path_ + "' has no object '" + object + "'");
  hid_t attr = H5Aopen(obj, name.c_str(), H5P_DEFAULT);
  double v = 0.0;
  const herr_t st = attr >= 0 ? H5Aread(attr, H5T_NATIVE_DOUBLE, &v) : -1;
  if (attr >= 0) H5Aclose(attr);
  H5Oclose(obj);
  if (st < 0) throw InputError("cannot read attribute '" + name + "' of '" + object + "' in '" + path_ + "'");
  return v;
}

std::vector<std::string> H5File::members(const std::string& group) const {
  std::vector<std::string> out;
  hid_t g = H5Gopen2(id_, group.c_str(), H5P_DEFAULT);
  if (g < 0) throw InputError("HDF5 file '" + path_ + "' has no group '" + group + "'");
  auto visit = [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->push_back(name);
    return 0;
  };
  H5Literate(g, H5_INDEX_NAME, H5_ITER_INC, nullptr, visit, &out);
  H5Gclose(g);
  return out;
}

bool H5File::has(const std::string& name) const {
  // Check each level: H5Lexists fails on a path whose parent is missing.
  std::size_t pos = 0;
  while (true) {
    pos = name.find('/', pos + 1);
    std::string part = name.substr(0, pos);
    if (H5Lexists(id_, part.c_str(), H5P_DEFAULT) <= 0) return false;
    if (pos == std::string::npos) return true;
  }
}

template <class T>
static std::vector<T> read_any(hid_t file, const std::string& path, const std::string& name, hid_t type,
                               std::size_t& rows, std::size_t& cols) {
  hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  if (set < 0) throw InputError("HDF5 file '" + path + "' has no dataset '" + name + "'");
  hid_t space = H5Dget_space(set);
  int rank = H5Sget_simple_extent_ndims(space);
  hsize_t dims[2] = {0, 1};
  if (rank < 1 || rank > 2) {
    H5Sclose(space);
    H5Dclose(set);
    throw InputError("dataset '" + name + "' in '" + path + "' must be 1-D or 2-D");
  }
  H5Sget_simple_extent_dims(space, dims, nullptr);
  rows = dims[0];
  cols = rank == 2 ? dims[1] : 1;
  std::vector<T> out(rows * cols);
  herr_t st = out.empty() ? 0 : H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
  H5Sclose(space);
  H5Dclose(set);
  if (st < 0) throw InputError("cannot read dataset '" + name + "' from '" + path + "'");
  return out;
}

std::vector<double> H5File::read_doubles(const std::string& name, std::size_t& rows, std::size_t& cols) const {
  return read_any<double>(id_, path_, name, H5T_NATIVE_DOUBLE, rows, cols);
}
std::vector<std::int64_t> H5File::read_ints(const std::string& name, std::size_t& rows, std::size_t& cols) const {
  return read_any<std::int64_t>(id_, path_, name, H5T_NATIVE_INT64, rows, cols);
}

std::string H5File::read_string_attribute(const std::string& name) const {
  hid_t attr = H5Aopen(id_, name.c_str(), H5P_DEFAULT);
  if (attr < 0) throw InputError("HDF5 file '" + path_ + "' has no attribute '" + name + "'");
  hid_t type = H5Aget_type(attr);
  std::string out(H5Tget_size(type), '\0');
  H5Aread(attr, type, out.data());
  H5Tclose(type);
  H5Aclose(attr);
  while (!out.empty() && out.back() == '\0') out.pop_back();
  return out;
}

bool H5File::has_attribute(const std::string& name) const { return H5Aexists(id_, name.c_str()) > 0; }

double H5File::read_double_attribute(const std::string& name) const {
  hid_t attr = H5Aopen(id_, name.c_str(), H5P_DEFAULT);
  if (attr < 0) throw InputError("HDF5 file '" + path_ + "' has no attribute '" + name + "'");
  double v = 0.0;
  herr_t st = H5Aread(attr, H5T_NATIVE_DOUBLE, &v);
  H5Aclose(attr);
  if (st < 0) throw InputError("cannot read attribute '" + name + "' of '" + path_ + "'");
  return v;
}

}  // namespace swarf
