// Subsurface stresses through the library (spec library-api.md §2.6): blocks of points are kept
// per problem, subs_calculate evaluates them at the last solution's tractions (module 1: every
// patch), subs_getresults returns columns of a block in column-major order.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <mutex>

#include "bindings/c/cntc_export.hpp"
#include "bindings/c/cntc_library.hpp"
#include "format/inp/to_model.hpp"
#include "format/inp/to_wheelrail.hpp"
#include "post/subsurface.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::cntc {
namespace {

constexpr int kMaxBlocks = 10;

/// Sorted, unique, positive element indices.
std::vector<int> index_list(const double* v, int n) {
  std::vector<int> out;
  for (int k = 0; k < n; ++k) {
    const int i = static_cast<int>(std::lround(v[k]));
    if (i > 0) out.push_back(i);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// The block of subs_addblock's arguments, lengths converted by `len` [mm per unit].
model::SubsurfaceBlock make_block(int isubs, int nx, int ny, int nz, const double* x,
                                  const double* y, const double* z, double len) {
  model::SubsurfaceBlock b;
  b.isubs = isubs;
  if (isubs == 2 || isubs == 6) {
    b.ixl = static_cast<int>(std::lround(x[0]));
    b.ixinc = std::max(1, static_cast<int>(std::lround(x[1])));
    b.ixh = static_cast<int>(std::lround(x[2]));
    b.iyl = static_cast<int>(std::lround(y[0]));
    b.iyinc = std::max(1, static_cast<int>(std::lround(y[1])));
    b.iyh = static_cast<int>(std::lround(y[2]));
  } else if (isubs == 3 || isubs == 7) {
    b.ix = index_list(x, nx);
    b.iy = index_list(y, ny);
  } else if (isubs == 9) {
    b.x.assign(x, x + nx);
    b.y.assign(y, y + ny);
    for (double& v : b.x) v *= len;
    for (double& v : b.y) v *= len;
  }
  if (isubs <= 3) {  // [NZ, ZL, DZ]
    const int count = std::max(1, static_cast<int>(std::lround(z[0])));
    b.zl = z[1] * len;
    b.dz = std::max(1e-9, z[2] * len);
    for (int k = 0; k < count; ++k) b.z.push_back(b.zl + k * b.dz);
  } else {
    b.z.assign(z, z + nz);
    for (double& v : b.z) v *= len;
  }
  for (auto* list : {&b.x, &b.y, &b.z}) std::sort(list->begin(), list->end());
  return b;
}

std::vector<SubsurfaceResult>* results_of(const Target& t) {
  if (t.m3 != nullptr) return &t.m3->subs_results;
  const std::size_t k = static_cast<std::size_t>(t.icp - 1);
  if (t.icp < 1 || k >= t.m1->subs_results.size()) return nullptr;
  return &t.m1->subs_results[k];
}

}  // namespace
}  // namespace rollcontact::cntc

using namespace rollcontact;
using namespace rollcontact::cntc;

CNTC_EXPORT void subs_addblock(int* ire, int* icp, int* iblk, int* isubs, int* nx, int* ny, int* nz,
                               double* xparam, double* yparam, double* zparam) {
  constexpr const char* name = "subs_addblock";
  const Target t = open_target(ire, icp, Access::Either, name);
  if (!t) return;
  if (iblk == nullptr || isubs == nullptr || nx == nullptr || ny == nullptr || nz == nullptr)
    return reject(name, "null argument");
  // Module 1: icp = -1 sets the blocks of every patch, a patch number that patch's own.
  auto& blocks = t.m3 != nullptr ? t.m3->subs_blocks
                 : t.icp == -1   ? t.m1->subs_blocks
                                 : t.m1->patch_subs_blocks[t.icp];
  const int nblock = static_cast<int>(blocks.size());
  if (*iblk < 0 || *iblk > std::min(kMaxBlocks, nblock + 1))
    return reject(name,
                  fmt::format("iblk = {} outside 0..{}", *iblk, std::min(kMaxBlocks, nblock + 1)));
  const int s = *isubs;
  if (s != 1 && s != 2 && s != 3 && s != 5 && s != 6 && s != 7 && s != 9)
    return reject(name, fmt::format("isubs = {} not one of 1, 2, 3, 5, 6, 7, 9", s));
  const bool counts_ok = (s == 1 && *nz == 3) || (s == 2 && *nx == 3 && *ny == 3 && *nz == 3) ||
                         (s == 3 && *nz == 3) || (s == 6 && *nx == 3 && *ny == 3) || s == 5 ||
                         s == 7 || s == 9;
  if (!counts_ok)
    return reject(name, fmt::format("isubs = {} with nx, ny, nz = {}, {}, {}", s, *nx, *ny, *nz));
  const bool need_xy = s == 2 || s == 3 || s == 6 || s == 7 || s == 9;
  if (*iblk > 0 && (zparam == nullptr || (need_xy && (xparam == nullptr || yparam == nullptr))))
    return reject(name, "null array");
  blocks.resize(static_cast<std::size_t>(std::max(0, *iblk - 1)));  // drop blocks >= iblk
  if (*iblk == 0) return;
  blocks.push_back(make_block(s, *nx, *ny, *nz, xparam, yparam, zparam, t.units().length));
}

CNTC_EXPORT void subs_calculate(int* ire, int* icp, int* ierror) {
  int code = 0;
  const Target t = open_target(ire, icp, Access::Either, "subs_calculate", &code);
  // Like cntc_calculate: one thread per problem at a time, 305 for another (§1.5).
  std::unique_lock<std::mutex> busy;
  if (t) {
    busy = std::unique_lock(t.m3 != nullptr ? t.m3->busy : t.m1->busy, std::try_to_lock);
    if (!busy.owns_lock()) {
      if (ierror != nullptr) *ierror = 305;
      return;
    }
  }
  try {
    if (t.m3 != nullptr && t.m3->result) {
      const model::Bodies bodies = format::to_patch_problem(t.m3->record).bodies;
      t.m3->subs_results = post::compute_subsurface(t.m3->subs_blocks, bodies, *t.m3->result);
    } else if (t.m1 != nullptr && t.m1->result) {
      const model::Bodies bodies = format::to_wheelrail_problem(t.m1->record).patch.bodies;
      t.m1->subs_results.clear();
      const auto& patches = t.m1->result->patches;
      for (std::size_t k = 0; k < patches.size(); ++k) {
        const auto own = t.m1->patch_subs_blocks.find(static_cast<int>(k) + 1);
        const auto& blocks = own != t.m1->patch_subs_blocks.end() ? own->second : t.m1->subs_blocks;
        t.m1->subs_results.push_back(post::compute_subsurface(blocks, bodies, patches[k].solution));
      }
    } else if (t) {
      library().log("subs_calculate: no solution yet (call cntc_calculate first)");
      code = CNTC_err_other;
    }
  } catch (const std::exception& e) {
    library().log(std::string("subs_calculate: ") + e.what());
    code = CNTC_err_other;
  }
  if (ierror != nullptr) *ierror = code;
}

CNTC_EXPORT void subs_getblocksize(int* ire, int* icp, int* iblk, int* nx, int* ny, int* nz) {
  if (nx == nullptr || ny == nullptr || nz == nullptr || iblk == nullptr) return;
  const Target t = open_target(ire, icp, Access::Results, "subs_getblocksize");
  if (!t) return;        // a refused access leaves the outputs alone (§1.3)
  *nx = *ny = *nz = -1;  // no such block
  const auto* results = results_of(t);
  if (results == nullptr || *iblk < 1 || *iblk > static_cast<int>(results->size())) return;
  const SubsurfaceResult& r = (*results)[static_cast<std::size_t>(*iblk - 1)];
  *nx = static_cast<int>(r.x.size());
  *ny = static_cast<int>(r.y.size());
  *nz = static_cast<int>(r.z.size());
}

CNTC_EXPORT void subs_getresults(int* ire, int* icp, int* iblk, int* lenarr, int* ncol, int* icol,
                                 double* values) {
  if (iblk == nullptr || lenarr == nullptr || ncol == nullptr || icol == nullptr ||
      values == nullptr)
    return;
  const Target t = open_target(ire, icp, Access::Results, "subs_getresults");
  if (!t) return;
  const auto* results = results_of(t);
  if (results == nullptr || *iblk < 1 || *iblk > static_cast<int>(results->size())) return;
  const SubsurfaceResult& r = (*results)[static_cast<std::size_t>(*iblk - 1)];
  const double len = t.units().length, pressure = t.units().pressure();
  const std::vector<double>* fields[] = {nullptr,   nullptr,  nullptr,  &r.ux,   &r.uy,   &r.uz,
                                         &r.sighyd, &r.sigvm, &r.sigtr, &r.sig1, &r.sig2, &r.sig3,
                                         &r.sxx,    &r.sxy,   &r.sxz,   &r.sxy,  &r.syy,  &r.syz,
                                         &r.sxz,    &r.syz,   &r.szz};
  const std::size_t nx = r.x.size(), ny = r.y.size(), n = r.size();
  const std::size_t rows = std::min(n, static_cast<std::size_t>(std::max(0, *lenarr)));
  for (int c = 0; c < *ncol; ++c) {
    const int col = icol[c];
    double* out = values + static_cast<std::size_t>(c) * static_cast<std::size_t>(*lenarr);
    for (std::size_t i = 0; i < rows; ++i) {
      const std::size_t ix = i % nx, iy = (i / nx) % ny, iz = i / (nx * ny);
      double v = -999.0;  // an invalid column (§2.6)
      if (col == 1) v = r.x[ix] / len;
      if (col == 2) v = r.y[iy] / len;
      if (col == 3) v = r.z[iz] / len;
      if (col >= 4 && col <= 6) v = (*fields[col - 1])[i] / len;
      if (col >= 7 && col <= 21) v = (*fields[col - 1])[i] / pressure;
      out[i] = v;
    }
  }
}
