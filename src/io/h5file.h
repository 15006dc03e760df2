// h5file.h: a small RAII wrapper over the HDF5 C API (serial library).
//
// Only what swarf needs: datasets of doubles and 64-bit integers shaped N or N x C, string
// and numeric attributes on the root, reading back with shape checks. Every failure throws
// InputError naming the file and the dataset, and HDF5's own error stack printing is off.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace swarf {

class H5File {
 public:
  enum class Mode { Read, Create };
  H5File(const std::string& path, Mode mode);
  ~H5File();
  H5File(const H5File&) = delete;
  H5File& operator=(const H5File&) = delete;

  const std::string& path() const { return path_; }
  /// Closes the file, flushing it; throws InputError naming the file when that fails (a full
  /// disk shows here). A writer calls it before renaming its .part file into place; the
  /// destructor closes without throwing.
  void close();

  /// Writes a rows x cols dataset (cols = 1 writes a 1-D dataset). Intermediate groups are created.
  void write(const std::string& name, const double* data, std::size_t rows, std::size_t cols = 1);
  void write(const std::string& name, const std::int64_t* data, std::size_t rows, std::size_t cols = 1);
  /// Stored as 64-bit integers, as the int64_t overload stores them: HDF5 widens the values in
  /// strips, so that no 64-bit copy of a large index array (the rods' ends) is made.
  void write(const std::string& name, const std::int32_t* data, std::size_t rows, std::size_t cols = 1);
  void write(const std::string& name, const std::uint8_t* data, std::size_t rows);
  /// Writes a rows x cols dataset of doubles (as write()) a strip of 'strip' rows at a time:
  /// fill(begin, end, values) puts rows [begin, end) into 'values' ((end - begin) x cols). No
  /// copy of the whole dataset is made (a million particles' stress tensors are 48 MB).
  void write_strips(const std::string& name, std::size_t rows, std::size_t cols, std::size_t strip,
                    const std::function<void(std::size_t, std::size_t, std::vector<double>&)>& fill);
  /// Writes a 1-D dataset of variable-length strings (group names, ...).
  void write_strings(const std::string& name, const std::vector<std::string>& values);
  /// Gives the dataset 'name' its attributes 'unit' (SI; "1" for numbers without unit) and
  /// 'description', so that the file explains itself.
  void describe(const std::string& name, const std::string& unit, const std::string& description);
  /// The paths of every dataset in the file ("/particles/position", ...), sorted.
  std::vector<std::string> datasets() const;
  /// A string attribute of the dataset 'name' ("" when it has none).
  std::string dataset_attribute(const std::string& name, const std::string& attribute) const;
  void write_attribute(const std::string& name, const std::string& value);
  void write_attribute(const std::string& name, double value);
  /// A numeric attribute on the group or dataset 'object' ("/frames/00000"), which must exist.
  void write_attribute(const std::string& object, const std::string& name, double value);

  bool has(const std::string& name) const;
  /// Reads a dataset; 'cols' receives 1 for 1-D datasets.
  std::vector<double> read_doubles(const std::string& name, std::size_t& rows, std::size_t& cols) const;
  std::vector<std::int64_t> read_ints(const std::string& name, std::size_t& rows, std::size_t& cols) const;
  std::string read_string_attribute(const std::string& name) const;
  bool has_attribute(const std::string& name) const;
  double read_double_attribute(const std::string& name) const;
  /// A numeric attribute of the group or dataset 'object'.
  double read_double_attribute(const std::string& object, const std::string& name) const;
  /// The names of the members of the group 'group' ("/frames"), in name order.
  std::vector<std::string> members(const std::string& group) const;

 private:
  std::string path_;
  long long id_ = -1;  // hid_t
};

}  // namespace swarf
