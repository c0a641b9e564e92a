// save_creep_lookup / load_creep_lookup (include/rollcontact/creep_lookup.hpp) with HDF5's C API.
// Layout: datasets /axes/{a_over_b,ksi,eta,phi} (1-D), /fx, /fy, /mz ([a/b][ξ̃][η̃][φ̃], doubles),
// string attributes format, method, normalisation, software and numeric ones version, mx,
// poisson_ratio on the root group. Written to a temporary name and renamed, so that a reader
// never sees half a file.

#include <fmt/format.h>
#include <hdf5.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "rollcontact/creep_lookup.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact {

namespace {

constexpr const char* kFormat = "rollcontact creep-force lookup table";
constexpr int kVersion = 1;
constexpr const char* kNormalisation =
    "ksi_n = G c^2 ksi/(mu FN), eta_n = G c^2 eta/(mu FN), phi_n = G c^3 phi/(mu FN), c = sqrt(a "
    "b);"
    " fx = Fx/(mu FN), fy = Fy/(mu FN), mz = Mz/(mu FN c)";

/// Closes an HDF5 identifier at scope exit.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  [[nodiscard]] hid_t get() const { return id_; }
  [[nodiscard]] bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void write_doubles(hid_t where, const char* name, const std::vector<double>& data,
                   const std::vector<hsize_t>& dims) {
  Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  Handle set(
      H5Dcreate2(where, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose);
  if (!set.ok() ||
      H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0)
    throw Error(fmt::format("HDF5: cannot write dataset {}", name));
}

void write_string_attribute(hid_t where, const char* name, const std::string& value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), value.empty() ? 1 : value.size());
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(H5Acreate2(where, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.ok() || H5Awrite(attr.get(), type.get(), value.c_str()) < 0)
    throw Error(fmt::format("HDF5: cannot write attribute {}", name));
}

template <class T>
void write_number_attribute(hid_t where, const char* name, T value, hid_t file_type,
                            hid_t memory_type) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(H5Acreate2(where, name, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.ok() || H5Awrite(attr.get(), memory_type, &value) < 0)
    throw Error(fmt::format("HDF5: cannot write attribute {}", name));
}

[[noreturn]] void malformed(const std::filesystem::path& path, const std::string& what) {
  throw InputError(path.string(), 0, "not a creep-force lookup table: " + what);
}

std::vector<double> read_doubles(hid_t where, const char* name, const std::filesystem::path& path,
                                 std::vector<hsize_t>& dims) {
  if (H5Lexists(where, name, H5P_DEFAULT) <= 0) malformed(path, fmt::format("no dataset {}", name));
  Handle set(H5Dopen2(where, name, H5P_DEFAULT), H5Dclose);
  Handle space(H5Dget_space(set.get()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (!set.ok() || rank < 1 || rank > 4)
    malformed(path, fmt::format("dataset {} unreadable", name));
  dims.assign(static_cast<std::size_t>(rank), 0);
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  std::size_t n = 1;
  for (const hsize_t d : dims) n *= static_cast<std::size_t>(d);
  std::vector<double> data(n);
  if (H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0)
    malformed(path, fmt::format("dataset {} unreadable", name));
  return data;
}

std::string read_string_attribute(hid_t where, const char* name) {
  if (H5Aexists(where, name) <= 0) return {};
  Handle attr(H5Aopen(where, name, H5P_DEFAULT), H5Aclose);
  Handle type(H5Aget_type(attr.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) > 0) return {};
  std::string value(H5Tget_size(type.get()), '\0');
  Handle memory(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(memory.get(), value.size());
  if (H5Aread(attr.get(), memory.get(), value.data()) < 0) return {};
  value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
  return value;
}

template <class T>
bool read_number_attribute(hid_t where, const char* name, hid_t memory_type, T& value) {
  if (H5Aexists(where, name) <= 0) return false;
  Handle attr(H5Aopen(where, name, H5P_DEFAULT), H5Aclose);
  return H5Aread(attr.get(), memory_type, &value) >= 0;
}

}  // namespace

void save_creep_lookup(const CreepLookupTable& table, const std::filesystem::path& path) {
  if (table.empty()) throw Error("an empty creep-force table cannot be saved");
  const CreepLookupAxes& ax = table.axes();
  std::filesystem::path temporary = path;
  temporary += ".part";
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions, not stderr noise
  {
    Handle file(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    if (!file.ok()) throw Error(fmt::format("cannot create {}", path.string()));
    const hid_t root = file.get();
    write_string_attribute(root, "format", kFormat);
    write_number_attribute(root, "version", kVersion, H5T_STD_I32LE, H5T_NATIVE_INT);
    write_string_attribute(root, "method", table.info().method);
    write_number_attribute(root, "mx", table.info().mx, H5T_STD_I32LE, H5T_NATIVE_INT);
    write_number_attribute(root, "poisson_ratio", table.info().poisson_ratio, H5T_IEEE_F64LE,
                           H5T_NATIVE_DOUBLE);
    write_string_attribute(root, "normalisation", kNormalisation);
    write_string_attribute(root, "software", table.info().software);
    Handle axes(H5Gcreate2(root, "axes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    write_doubles(axes.get(), "a_over_b", ax.a_over_b, {ax.a_over_b.size()});
    write_doubles(axes.get(), "ksi", ax.ksi, {ax.ksi.size()});
    write_doubles(axes.get(), "eta", ax.eta, {ax.eta.size()});
    write_doubles(axes.get(), "phi", ax.phi, {ax.phi.size()});
    const std::vector<hsize_t> dims{ax.a_over_b.size(), ax.ksi.size(), ax.eta.size(),
                                    ax.phi.size()};
    const std::size_t n = table.values().size();
    std::vector<double> fx(n), fy(n), mz(n);
    for (std::size_t i = 0; i < n; ++i) {
      fx[i] = table.values()[i].fx;
      fy[i] = table.values()[i].fy;
      mz[i] = table.values()[i].mz;
    }
    write_doubles(root, "fx", fx, dims);
    write_doubles(root, "fy", fy, dims);
    write_doubles(root, "mz", mz, dims);
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw Error(fmt::format("cannot write {}", path.string()));
  }
}

CreepLookupTable load_creep_lookup(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path.string(), 0, "creep-force lookup table not found");
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  if (H5Fis_hdf5(path.c_str()) <= 0) malformed(path, "not an HDF5 file");
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.ok()) throw InputError(path.string(), 0, "cannot open the HDF5 file");
  const hid_t root = file.get();
  if (read_string_attribute(root, "format") != kFormat) malformed(path, "no format attribute");
  int version = 0;
  if (!read_number_attribute(root, "version", H5T_NATIVE_INT, version) || version != kVersion)
    malformed(path, fmt::format("version {} (this program reads {})", version, kVersion));
  CreepLookupInfo info;
  info.method = read_string_attribute(root, "method");
  info.software = read_string_attribute(root, "software");
  read_number_attribute(root, "mx", H5T_NATIVE_INT, info.mx);
  read_number_attribute(root, "poisson_ratio", H5T_NATIVE_DOUBLE, info.poisson_ratio);
  if (H5Lexists(root, "axes", H5P_DEFAULT) <= 0) malformed(path, "no group /axes");
  Handle axes_group(H5Gopen2(root, "axes", H5P_DEFAULT), H5Gclose);
  std::vector<hsize_t> dims;
  CreepLookupAxes axes;
  axes.a_over_b = read_doubles(axes_group.get(), "a_over_b", path, dims);
  axes.ksi = read_doubles(axes_group.get(), "ksi", path, dims);
  axes.eta = read_doubles(axes_group.get(), "eta", path, dims);
  axes.phi = read_doubles(axes_group.get(), "phi", path, dims);
  const std::vector<hsize_t> expected{axes.a_over_b.size(), axes.ksi.size(), axes.eta.size(),
                                      axes.phi.size()};
  std::array<std::vector<double>, 3> fields;
  const char* names[3] = {"fx", "fy", "mz"};
  for (int k = 0; k < 3; ++k) {
    fields[static_cast<std::size_t>(k)] = read_doubles(root, names[k], path, dims);
    if (dims != expected)
      malformed(path, fmt::format("dataset {} does not match the axes", names[k]));
  }
  std::vector<CreepLookupValue> values(fields[0].size());
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = {fields[0][i], fields[1][i], fields[2][i]};
  try {
    return CreepLookupTable(std::move(axes), std::move(values), std::move(info));
  } catch (const InvalidValueError& e) {
    malformed(path, e.what());
  }
}

}  // namespace rollcontact
