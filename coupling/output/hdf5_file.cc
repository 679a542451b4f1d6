// HDF5 output through the C API. Errors are turned into exceptions naming the file and the
// dataset; HDF5's own error stack printing is silenced so a failure is one clear message.
#include "coupling/output/hdf5_file.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace wear::coupling {

namespace {
void check(bool ok, const std::string& path, const std::string& what) {
  if (!ok)
    throw std::runtime_error("HDF5 file '" + path + "': cannot " + what);
}
} // namespace

Hdf5File::Hdf5File(std::string path)
    : path_(std::move(path)), tmp_(path_ + ".tmp." + std::to_string(::getpid())) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  file_ = H5Fcreate(tmp_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  check(file_ >= 0, tmp_, "create it (is the folder writable?)");
}

Hdf5File::~Hdf5File() {
  if (file_ >= 0) {
    H5Fclose(file_);
    std::remove(tmp_.c_str());
  }
}

void Hdf5File::write_raw(const std::string& name, hid_t type, const void* data,
                         const std::vector<std::size_t>& dims, std::size_t n) {
  std::vector<hsize_t> d(dims.begin(), dims.end());
  std::size_t product = 1;
  for (auto v : dims)
    product *= v;
  if (product != n)
    throw std::logic_error("HDF5 dataset '" + name + "': shape does not match the data size");
  const hid_t space = H5Screate_simple(int(d.size()), d.data(), nullptr);
  const hid_t links = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(links, 1);
  const hid_t set = H5Dcreate2(file_, name.c_str(), type, space, links, H5P_DEFAULT, H5P_DEFAULT);
  H5Pclose(links);
  H5Sclose(space);
  check(set >= 0, path_, "create dataset '" + name + "'");
  const herr_t status = n ? H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) : 0;
  H5Dclose(set);
  check(status >= 0, path_, "write dataset '" + name + "'");
}

void Hdf5File::write_text(const std::string& name, const std::string& text) {
  write_raw(name, H5T_NATIVE_CHAR, text.data(), {text.size()}, text.size());
}

void Hdf5File::write(const std::string& name, const std::vector<double>& data,
                     const std::vector<std::size_t>& dims) {
  write_raw(name, H5T_NATIVE_DOUBLE, data.data(), dims, data.size());
}
void Hdf5File::write(const std::string& name, const std::vector<std::int64_t>& data,
                     const std::vector<std::size_t>& dims) {
  write_raw(name, H5T_NATIVE_INT64, data.data(), dims, data.size());
}
void Hdf5File::write(const std::string& name, const std::vector<int>& data,
                     const std::vector<std::size_t>& dims) {
  write_raw(name, H5T_NATIVE_INT, data.data(), dims, data.size());
}

void Hdf5File::attribute(const std::string& object, const std::string& name, double value) {
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate_by_name(file_, object.c_str(), name.c_str(), H5T_NATIVE_DOUBLE, space,
                                    H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Sclose(space);
  check(a >= 0, path_, "create attribute '" + name + "' on '" + object + "'");
  const herr_t status = H5Awrite(a, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(a);
  check(status >= 0, path_, "write attribute '" + name + "'");
}

void Hdf5File::attribute(const std::string& object, const std::string& name,
                         const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, std::max<std::size_t>(1, value.size()));
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate_by_name(file_, object.c_str(), name.c_str(), type, space, H5P_DEFAULT,
                                    H5P_DEFAULT, H5P_DEFAULT);
  H5Sclose(space);
  check(a >= 0, path_, "create attribute '" + name + "' on '" + object + "'");
  const herr_t status = H5Awrite(a, type, value.c_str());
  H5Aclose(a);
  H5Tclose(type);
  check(status >= 0, path_, "write attribute '" + name + "'");
}

void Hdf5File::commit(const std::string& previous) {
  const herr_t status = H5Fclose(file_);
  file_ = -1;
  if (status < 0) {
    std::remove(tmp_.c_str());
    check(false, path_, "close it");
  }
  std::error_code ec;
  if (!previous.empty() && std::filesystem::exists(path_)) {
    const std::string kept = previous + ".tmp." + std::to_string(getpid());
    std::filesystem::remove(kept, ec);
    std::filesystem::create_hard_link(path_, kept, ec);
    if (ec)
      std::filesystem::copy_file(path_, kept, std::filesystem::copy_options::overwrite_existing,
                                 ec);
    if (!ec)
      std::filesystem::rename(kept, previous, ec);
    if (ec) {
      std::remove(tmp_.c_str());
      std::remove(kept.c_str());
      check(false, previous, "keep the file it replaces there (" + ec.message() + ")");
    }
  }
  std::filesystem::rename(tmp_, path_, ec);
  if (ec) {
    std::remove(tmp_.c_str());
    check(false, path_, "rename it into place (" + ec.message() + ")");
  }
}

Hdf5Reader::Hdf5Reader(std::string path) : path_(std::move(path)) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  if (!std::filesystem::exists(path_))
    throw std::runtime_error("HDF5 file '" + path_ + "' does not exist");
  file_ = H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  check(file_ >= 0, path_, "open it (not an HDF5 file, or damaged)");
}

Hdf5Reader::~Hdf5Reader() {
  if (file_ >= 0)
    H5Fclose(file_);
}

std::vector<std::size_t> Hdf5Reader::dims(const std::string& name) const {
  const hid_t set = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
  check(set >= 0, path_, "find the dataset '" + name + "'");
  const hid_t space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> d(std::max(rank, 0));
  if (rank > 0)
    H5Sget_simple_extent_dims(space, d.data(), nullptr);
  H5Sclose(space);
  H5Dclose(set);
  check(rank >= 0, path_, "read the shape of '" + name + "'");
  return {d.begin(), d.end()};
}

void Hdf5Reader::read_raw(const std::string& name, hid_t type, void* data, std::size_t n) const {
  const hid_t set = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
  check(set >= 0, path_, "find the dataset '" + name + "'");
  const herr_t status = n ? H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) : 0;
  H5Dclose(set);
  check(status >= 0, path_, "read the dataset '" + name + "' (damaged file?)");
}

namespace {
std::size_t n_values(const std::vector<std::size_t>& d) {
  std::size_t n = 1;
  for (auto x : d)
    n *= x;
  return n;
}
} // namespace

std::vector<double> Hdf5Reader::doubles(const std::string& name) const {
  std::vector<double> v(n_values(dims(name)));
  read_raw(name, H5T_NATIVE_DOUBLE, v.data(), v.size());
  return v;
}

std::vector<std::int64_t> Hdf5Reader::int64s(const std::string& name) const {
  std::vector<std::int64_t> v(n_values(dims(name)));
  read_raw(name, H5T_NATIVE_INT64, v.data(), v.size());
  return v;
}

std::string Hdf5Reader::text(const std::string& name) const {
  std::string t(n_values(dims(name)), '\0');
  read_raw(name, H5T_NATIVE_CHAR, t.data(), t.size());
  return t;
}

std::vector<int> Hdf5Reader::ints(const std::string& name) const {
  std::vector<int> v(n_values(dims(name)));
  read_raw(name, H5T_NATIVE_INT, v.data(), v.size());
  return v;
}

double Hdf5Reader::attribute(const std::string& object, const std::string& name) const {
  const hid_t a = H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  check(a >= 0, path_, "find the attribute '" + name + "' of '" + object + "'");
  double v = 0;
  const herr_t status = H5Aread(a, H5T_NATIVE_DOUBLE, &v);
  H5Aclose(a);
  check(status >= 0, path_, "read the attribute '" + name + "' of '" + object + "'");
  return v;
}

bool Hdf5Reader::has_attribute(const std::string& object, const std::string& name) const {
  return H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

bool Hdf5Reader::has_object(const std::string& name) const {
  return H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0;
}

std::string Hdf5Reader::text_attribute(const std::string& object, const std::string& name) const {
  const hid_t a = H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  check(a >= 0, path_, "find the attribute '" + name + "' of '" + object + "'");
  const hid_t type = H5Aget_type(a);
  const std::size_t size = H5Tget_size(type);
  std::string v(size, '\0');
  const herr_t status = H5Aread(a, type, v.data());
  H5Tclose(type);
  H5Aclose(a);
  check(status >= 0, path_, "read the attribute '" + name + "' of '" + object + "'");
  while (!v.empty() && v.back() == '\0')
    v.pop_back();
  return v;
}

} // namespace wear::coupling
