// save_creep_lookup / load_creep_lookup (include/rollcontact/creep_lookup.hpp) with HDF5's C API.
// Layout: datasets /axes/{a_over_b,ksi,eta,phi} (1-D), /fx, /fy, /mz ([a/b][ξ̃][η̃][φ̃], doubles),
// string attributes format, method, normalisation, software and numeric ones version, mx,
// poisson_ratio on the root group. Written to a temporary name and renamed, so that a reader
// never sees half a file.
//
// HDF5 is loaded when a table is read or written (dlopen), not linked: linked, libhdf5 and what
// it pulls in (libcurl, GnuTLS, Kerberos, LDAP …) were loaded and initialised at the start of
// every process, ≈ 4–5 ms of each `rollcontact run` on the benchmark machine (issue 16).

#include <dlfcn.h>
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

/// The part of HDF5's C API used here, resolved in the library named at configure time.
/// The library stays loaded (RTLD_NODELETE: HDF5 registers its own exit handler).
class Hdf5Api {
 public:
  Hdf5Api() {
    handle_ = dlopen(ROLLCONTACT_HDF5_LIBRARY, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (handle_ == nullptr)
      throw Error(
          fmt::format("cannot load the HDF5 library {}: {}", ROLLCONTACT_HDF5_LIBRARY, dlerror()));
    resolve_functions();
    if (open() < 0) throw Error("the HDF5 library could not be initialised");
    // The type macros (H5T_NATIVE_DOUBLE …) read these globals after H5open().
    ieee_f64le = global("H5T_IEEE_F64LE_g");
    std_i32le = global("H5T_STD_I32LE_g");
    c_s1 = global("H5T_C_S1_g");
    native_int = global("H5T_NATIVE_INT_g");
    native_double = global("H5T_NATIVE_DOUBLE_g");
  }
  ~Hdf5Api() { dlclose(handle_); }
  Hdf5Api(const Hdf5Api&) = delete;
  Hdf5Api& operator=(const Hdf5Api&) = delete;

  // H5F_ACC_TRUNC and H5F_ACC_RDONLY without their macros (which call H5check and H5open).
  static constexpr unsigned acc_trunc = 0x0002u, acc_rdonly = 0x0000u;
  hid_t ieee_f64le = -1, std_i32le = -1, c_s1 = -1, native_int = -1, native_double = -1;

  decltype(&::H5open) open = nullptr;
  decltype(&::H5Eset_auto2) eset_auto = nullptr;
  decltype(&::H5Fcreate) file_create = nullptr;
  decltype(&::H5Fopen) file_open = nullptr;
  decltype(&::H5Fclose) file_close = nullptr;
  decltype(&::H5Fis_hdf5) file_is_hdf5 = nullptr;
  decltype(&::H5Gcreate2) gcreate = nullptr;
  decltype(&::H5Gopen2) gopen = nullptr;
  decltype(&::H5Gclose) gclose = nullptr;
  decltype(&::H5Lexists) lexists = nullptr;
  decltype(&::H5Screate) screate = nullptr;
  decltype(&::H5Screate_simple) screate_simple = nullptr;
  decltype(&::H5Sclose) sclose = nullptr;
  decltype(&::H5Sget_simple_extent_ndims) sget_ndims = nullptr;
  decltype(&::H5Sget_simple_extent_dims) sget_dims = nullptr;
  decltype(&::H5Dcreate2) dcreate = nullptr;
  decltype(&::H5Dopen2) dopen = nullptr;
  decltype(&::H5Dclose) dclose = nullptr;
  decltype(&::H5Dwrite) dwrite = nullptr;
  decltype(&::H5Dread) dread = nullptr;
  decltype(&::H5Dget_space) dget_space = nullptr;
  decltype(&::H5Tcopy) tcopy = nullptr;
  decltype(&::H5Tclose) tclose = nullptr;
  decltype(&::H5Tset_size) tset_size = nullptr;
  decltype(&::H5Tget_size) tget_size = nullptr;
  decltype(&::H5Tget_class) tget_class = nullptr;
  decltype(&::H5Tis_variable_str) tis_variable_str = nullptr;
  decltype(&::H5Acreate2) acreate = nullptr;
  decltype(&::H5Aopen) aopen = nullptr;
  decltype(&::H5Aclose) aclose = nullptr;
  decltype(&::H5Awrite) awrite = nullptr;
  decltype(&::H5Aread) aread = nullptr;
  decltype(&::H5Aexists) aexists = nullptr;
  decltype(&::H5Aget_type) aget_type = nullptr;

 private:
  void* symbol(const char* name) const {
    void* p = dlsym(handle_, name);
    if (p == nullptr) throw Error(fmt::format("the HDF5 library lacks {}", name));
    return p;
  }
  template <class F>
  void resolve(F& f, const char* name) const {
    f = reinterpret_cast<F>(symbol(name));
  }
  hid_t global(const char* name) const { return *static_cast<const hid_t*>(symbol(name)); }

  void resolve_functions() {
    resolve(open, "H5open");
    resolve(eset_auto, "H5Eset_auto2");
    resolve(file_create, "H5Fcreate");
    resolve(file_open, "H5Fopen");
    resolve(file_close, "H5Fclose");
    resolve(file_is_hdf5, "H5Fis_hdf5");
    resolve(gcreate, "H5Gcreate2");
    resolve(gopen, "H5Gopen2");
    resolve(gclose, "H5Gclose");
    resolve(lexists, "H5Lexists");
    resolve(screate, "H5Screate");
    resolve(screate_simple, "H5Screate_simple");
    resolve(sclose, "H5Sclose");
    resolve(sget_ndims, "H5Sget_simple_extent_ndims");
    resolve(sget_dims, "H5Sget_simple_extent_dims");
    resolve(dcreate, "H5Dcreate2");
    resolve(dopen, "H5Dopen2");
    resolve(dclose, "H5Dclose");
    resolve(dwrite, "H5Dwrite");
    resolve(dread, "H5Dread");
    resolve(dget_space, "H5Dget_space");
    resolve(tcopy, "H5Tcopy");
    resolve(tclose, "H5Tclose");
    resolve(tset_size, "H5Tset_size");
    resolve(tget_size, "H5Tget_size");
    resolve(tget_class, "H5Tget_class");
    resolve(tis_variable_str, "H5Tis_variable_str");
    resolve(acreate, "H5Acreate2");
    resolve(aopen, "H5Aopen");
    resolve(aclose, "H5Aclose");
    resolve(awrite, "H5Awrite");
    resolve(aread, "H5Aread");
    resolve(aexists, "H5Aexists");
    resolve(aget_type, "H5Aget_type");
  }

  void* handle_ = nullptr;
};

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

void write_doubles(const Hdf5Api& h5, hid_t where, const char* name,
                   const std::vector<double>& data, const std::vector<hsize_t>& dims) {
  Handle space(h5.screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), h5.sclose);
  Handle set(
      h5.dcreate(where, name, h5.ieee_f64le, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      h5.dclose);
  if (!set.ok() ||
      h5.dwrite(set.get(), h5.native_double, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0)
    throw Error(fmt::format("HDF5: cannot write dataset {}", name));
}

void write_string_attribute(const Hdf5Api& h5, hid_t where, const char* name,
                            const std::string& value) {
  Handle type(h5.tcopy(h5.c_s1), h5.tclose);
  h5.tset_size(type.get(), value.empty() ? 1 : value.size());
  Handle space(h5.screate(H5S_SCALAR), h5.sclose);
  Handle attr(h5.acreate(where, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
              h5.aclose);
  if (!attr.ok() || h5.awrite(attr.get(), type.get(), value.c_str()) < 0)
    throw Error(fmt::format("HDF5: cannot write attribute {}", name));
}

template <class T>
void write_number_attribute(const Hdf5Api& h5, hid_t where, const char* name, T value,
                            hid_t file_type, hid_t memory_type) {
  Handle space(h5.screate(H5S_SCALAR), h5.sclose);
  Handle attr(h5.acreate(where, name, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), h5.aclose);
  if (!attr.ok() || h5.awrite(attr.get(), memory_type, &value) < 0)
    throw Error(fmt::format("HDF5: cannot write attribute {}", name));
}

[[noreturn]] void malformed(const std::filesystem::path& path, const std::string& what) {
  throw InputError(path.string(), 0, "not a creep-force lookup table: " + what);
}

std::vector<double> read_doubles(const Hdf5Api& h5, hid_t where, const char* name,
                                 const std::filesystem::path& path, std::vector<hsize_t>& dims) {
  if (h5.lexists(where, name, H5P_DEFAULT) <= 0)
    malformed(path, fmt::format("no dataset {}", name));
  Handle set(h5.dopen(where, name, H5P_DEFAULT), h5.dclose);
  Handle space(h5.dget_space(set.get()), h5.sclose);
  const int rank = h5.sget_ndims(space.get());
  if (!set.ok() || rank < 1 || rank > 4)
    malformed(path, fmt::format("dataset {} unreadable", name));
  dims.assign(static_cast<std::size_t>(rank), 0);
  h5.sget_dims(space.get(), dims.data(), nullptr);
  std::size_t n = 1;
  for (const hsize_t d : dims) n *= static_cast<std::size_t>(d);
  std::vector<double> data(n);
  if (h5.dread(set.get(), h5.native_double, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0)
    malformed(path, fmt::format("dataset {} unreadable", name));
  return data;
}

std::string read_string_attribute(const Hdf5Api& h5, hid_t where, const char* name) {
  if (h5.aexists(where, name) <= 0) return {};
  Handle attr(h5.aopen(where, name, H5P_DEFAULT), h5.aclose);
  Handle type(h5.aget_type(attr.get()), h5.tclose);
  if (h5.tget_class(type.get()) != H5T_STRING || h5.tis_variable_str(type.get()) > 0) return {};
  std::string value(h5.tget_size(type.get()), '\0');
  Handle memory(h5.tcopy(h5.c_s1), h5.tclose);
  h5.tset_size(memory.get(), value.size());
  if (h5.aread(attr.get(), memory.get(), value.data()) < 0) return {};
  value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
  return value;
}

template <class T>
bool read_number_attribute(const Hdf5Api& h5, hid_t where, const char* name, hid_t memory_type,
                           T& value) {
  if (h5.aexists(where, name) <= 0) return false;
  Handle attr(h5.aopen(where, name, H5P_DEFAULT), h5.aclose);
  return h5.aread(attr.get(), memory_type, &value) >= 0;
}

}  // namespace

void save_creep_lookup(const CreepLookupTable& table, const std::filesystem::path& path) {
  if (table.empty()) throw Error("an empty creep-force table cannot be saved");
  const CreepLookupAxes& ax = table.axes();
  std::filesystem::path temporary = path;
  temporary += ".part";
  const Hdf5Api h5;
  h5.eset_auto(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions, not stderr noise
  {
    Handle file(h5.file_create(temporary.c_str(), Hdf5Api::acc_trunc, H5P_DEFAULT, H5P_DEFAULT),
                h5.file_close);
    if (!file.ok()) throw Error(fmt::format("cannot create {}", path.string()));
    const hid_t root = file.get();
    write_string_attribute(h5, root, "format", kFormat);
    write_number_attribute(h5, root, "version", kVersion, h5.std_i32le, h5.native_int);
    write_string_attribute(h5, root, "method", table.info().method);
    write_number_attribute(h5, root, "mx", table.info().mx, h5.std_i32le, h5.native_int);
    write_number_attribute(h5, root, "poisson_ratio", table.info().poisson_ratio, h5.ieee_f64le,
                           h5.native_double);
    write_string_attribute(h5, root, "normalisation", kNormalisation);
    write_string_attribute(h5, root, "software", table.info().software);
    Handle axes(h5.gcreate(root, "axes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), h5.gclose);
    write_doubles(h5, axes.get(), "a_over_b", ax.a_over_b, {ax.a_over_b.size()});
    write_doubles(h5, axes.get(), "ksi", ax.ksi, {ax.ksi.size()});
    write_doubles(h5, axes.get(), "eta", ax.eta, {ax.eta.size()});
    write_doubles(h5, axes.get(), "phi", ax.phi, {ax.phi.size()});
    const std::vector<hsize_t> dims{ax.a_over_b.size(), ax.ksi.size(), ax.eta.size(),
                                    ax.phi.size()};
    const std::size_t n = table.values().size();
    std::vector<double> fx(n), fy(n), mz(n);
    for (std::size_t i = 0; i < n; ++i) {
      fx[i] = table.values()[i].fx;
      fy[i] = table.values()[i].fy;
      mz[i] = table.values()[i].mz;
    }
    write_doubles(h5, root, "fx", fx, dims);
    write_doubles(h5, root, "fy", fy, dims);
    write_doubles(h5, root, "mz", mz, dims);
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
  const Hdf5Api h5;
  h5.eset_auto(H5E_DEFAULT, nullptr, nullptr);
  if (h5.file_is_hdf5(path.c_str()) <= 0) malformed(path, "not an HDF5 file");
  Handle file(h5.file_open(path.c_str(), Hdf5Api::acc_rdonly, H5P_DEFAULT), h5.file_close);
  if (!file.ok()) throw InputError(path.string(), 0, "cannot open the HDF5 file");
  const hid_t root = file.get();
  if (read_string_attribute(h5, root, "format") != kFormat) malformed(path, "no format attribute");
  int version = 0;
  if (!read_number_attribute(h5, root, "version", h5.native_int, version) || version != kVersion)
    malformed(path, fmt::format("version {} (this program reads {})", version, kVersion));
  CreepLookupInfo info;
  info.method = read_string_attribute(h5, root, "method");
  info.software = read_string_attribute(h5, root, "software");
  read_number_attribute(h5, root, "mx", h5.native_int, info.mx);
  read_number_attribute(h5, root, "poisson_ratio", h5.native_double, info.poisson_ratio);
  if (h5.lexists(root, "axes", H5P_DEFAULT) <= 0) malformed(path, "no group /axes");
  Handle axes_group(h5.gopen(root, "axes", H5P_DEFAULT), h5.gclose);
  std::vector<hsize_t> dims;
  CreepLookupAxes axes;
  axes.a_over_b = read_doubles(h5, axes_group.get(), "a_over_b", path, dims);
  axes.ksi = read_doubles(h5, axes_group.get(), "ksi", path, dims);
  axes.eta = read_doubles(h5, axes_group.get(), "eta", path, dims);
  axes.phi = read_doubles(h5, axes_group.get(), "phi", path, dims);
  const std::vector<hsize_t> expected{axes.a_over_b.size(), axes.ksi.size(), axes.eta.size(),
                                      axes.phi.size()};
  std::array<std::vector<double>, 3> fields;
  const char* names[3] = {"fx", "fy", "mz"};
  for (int k = 0; k < 3; ++k) {
    fields[static_cast<std::size_t>(k)] = read_doubles(h5, root, names[k], path, dims);
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
