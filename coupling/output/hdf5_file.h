#pragma once
// A minimal HDF5 writer (C API of the library deal.II links, so one HDF5 per process) that
// writes atomically: datasets go to "<path>.tmp.<pid>", which is renamed over <path> by
// commit(). Intermediate groups are created on demand.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace wear::coupling {

class Hdf5File {
public:
  explicit Hdf5File(std::string path);
  ~Hdf5File(); ///< without commit(): the temporary file is removed, the old file kept
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;

  /// Row-major dataset of shape dims (product must equal data.size()).
  void write(const std::string& name, const std::vector<double>& data,
             const std::vector<std::size_t>& dims);
  void write(const std::string& name, const std::vector<std::int64_t>& data,
             const std::vector<std::size_t>& dims);
  void write(const std::string& name, const std::vector<int>& data,
             const std::vector<std::size_t>& dims);
  /// A text of any length as a dataset of bytes (an attribute holds at most 64 KiB).
  void write_text(const std::string& name, const std::string& text);
  /// Attributes on an existing object (group or dataset); "/" is the root.
  void attribute(const std::string& object, const std::string& name, double value);
  void attribute(const std::string& object, const std::string& name, const std::string& value);

  /// Closes the file and renames it into place. Throws naming the path on failure. With
  /// `previous`, the file it replaces is first kept under that name (a hard link, or a copy
  /// where links are not possible), so a complete old and new file exist at every moment.
  void commit(const std::string& previous = "");

private:
  void write_raw(const std::string& name, hid_t type, const void* data,
                 const std::vector<std::size_t>& dims, std::size_t n);
  std::string path_, tmp_;
  hid_t file_ = -1;
};

/// Reads what Hdf5File wrote. Every failure (missing file, not HDF5, missing dataset, wrong
/// size) throws naming the file and the dataset.
class Hdf5Reader {
public:
  explicit Hdf5Reader(std::string path);
  ~Hdf5Reader();
  Hdf5Reader(const Hdf5Reader&) = delete;
  Hdf5Reader& operator=(const Hdf5Reader&) = delete;

  std::vector<std::size_t> dims(const std::string& name) const;
  std::vector<double> doubles(const std::string& name) const;
  std::vector<std::int64_t> int64s(const std::string& name) const;
  std::vector<int> ints(const std::string& name) const;
  double attribute(const std::string& object, const std::string& name) const;
  bool has_attribute(const std::string& object, const std::string& name) const;
  /// Whether a group or dataset `name` ("/dem") exists.
  bool has_object(const std::string& name) const;
  std::string text_attribute(const std::string& object, const std::string& name) const;
  /// A text written by Hdf5File::write_text.
  std::string text(const std::string& name) const;
  const std::string& path() const { return path_; }

private:
  void read_raw(const std::string& name, hid_t type, void* data, std::size_t n) const;
  std::string path_;
  hid_t file_ = -1;
};

} // namespace wear::coupling
