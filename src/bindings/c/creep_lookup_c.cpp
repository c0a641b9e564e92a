// The C interface of creep-force lookup tables (include/rollcontact/creep_lookup.h).

#include <algorithm>
#include <cstring>
#include <exception>
#include <new>
#include <string>

#include "bindings/c/cntc_export.hpp"
#include "rollcontact/creep_lookup.h"
#include "rollcontact/creep_lookup.hpp"

struct rc_creep_lookup {
  rollcontact::CreepLookupTable table;
};

namespace {

void set_error(char* error, int error_len, const std::string& message) {
  if (error == nullptr || error_len <= 0) return;
  const std::size_t n = std::min(message.size(), static_cast<std::size_t>(error_len - 1));
  std::memcpy(error, message.data(), n);
  error[n] = '\0';
}

}  // namespace

CNTC_EXPORT rc_creep_lookup* rc_creep_lookup_open(const char* path, char* error, int error_len) {
  set_error(error, error_len, "");
  if (path == nullptr) {
    set_error(error, error_len, "no file name");
    return nullptr;
  }
  try {
    return new rc_creep_lookup{rollcontact::load_creep_lookup(path)};
  } catch (const std::exception& e) {
    set_error(error, error_len, e.what());
  }
  return nullptr;
}

CNTC_EXPORT void rc_creep_lookup_close(rc_creep_lookup* table) {
  delete table;
}

CNTC_EXPORT void rc_creep_lookup_eval(const rc_creep_lookup* table, double a_over_b, double ksi_n,
                                      double eta_n, double phi_n, double out[3]) {
  if (out == nullptr) return;
  const rollcontact::CreepLookupValue v = table != nullptr
                                              ? table->table.evaluate(a_over_b, ksi_n, eta_n, phi_n)
                                              : rollcontact::CreepLookupValue{};
  out[0] = v.fx;
  out[1] = v.fy;
  out[2] = v.mz;
}

CNTC_EXPORT void rc_creep_lookup_forces(const rc_creep_lookup* table, double a, double b, double fn,
                                        double g, double mu, double ksi, double eta, double phi,
                                        double out[3]) {
  if (out == nullptr) return;
  const rollcontact::CreepLookupForces f = table != nullptr
                                               ? table->table.forces(a, b, fn, g, mu, ksi, eta, phi)
                                               : rollcontact::CreepLookupForces{};
  out[0] = f.fx_N;
  out[1] = f.fy_N;
  out[2] = f.mz_Nmm;
}
