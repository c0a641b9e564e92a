#include "bindings/c/cntc_library.hpp"

#include <fmt/format.h>

#include <cstring>
#include <filesystem>
#include <iostream>

#include "rollcontact/contact_addon.h"

namespace rollcontact::cntc {

namespace {

constexpr int kMaxActiveElements = 100;  // MAX_NUM_REs
constexpr int kMaxIcp = 9;               // MAX_CPids

const char* category_name(Access a) {
  switch (a) {
    case Access::Module3:
      return "module 3";
    case Access::Module1:
    case Access::Module1Patch:
    case Access::Module1Forces:
      return "module 1";
    default:
      return "modules 1 and 3";
  }
}

}  // namespace

bool units_for_code(int code, Units& units) {
  switch (code) {
    case 1934:
    case 1937:  // imperial: not implemented in CONTACT either, behaves like CONTACT units
      units = Units{code, 1.0, 1.0, 1.0};
      return true;
    case 1935:
      units = Units{code, 1e3, 1e3, -1.0};
      return true;
    case 1936:
      units = Units{code, 1e3, 1e3, 1.0};
      return true;
    default:
      return false;
  }
}

Module3Problem::Module3Problem() {
  // A fresh problem (§5 "Default values"): CONTACT units, N = 0, no output files, no potential
  // contact yet; the elastic constants of steel and Coulomb friction 0.3 until set.
  format::ControlDigits& d = record.digits;
  d.p = 2;
  d.n = 0;
  d.a = 0;
  d.o = 0;
  d.w = 1;
  d.d = 2;
  d.c = 2;
  d.z = 2;
  record.result_element = 0;
}

Module1Problem::Module1Problem() {
  // A fresh wheel/rail problem (§5 "Default values"): right wheel on a track, steady rolling,
  // the position prescribed (N = 0: setverticalforce sets N = 1), no profiles yet.
  format::ControlDigits& d = record.digits;
  d.p = 2;
  d.t = 3;
  d.n = 0;
  d.d = 2;
  d.c = 2;
  d.a = 0;
  d.o = 0;
  d.w = 1;
  d.z = 3;
  d.e = 3;
  record.config = 1;
}

std::string c_string(const char* s, const int* len) {
  if (s == nullptr || len == nullptr || *len <= 0) return {};
  const std::size_t n = static_cast<std::size_t>(*len);
  std::string out(s, strnlen(s, n));
  const auto last = out.find_last_not_of(' ');
  return last == std::string::npos ? std::string{} : out.substr(0, last + 1);
}

bool Library::initialize_first(int output_to_screen, const std::string& wrkdir,
                               const std::string& outdir, const std::string& expnam) {
  std::lock_guard lock(mutex_);
  if (initialised_) return false;
  initialised_ = true;
  to_screen_ = output_to_screen == 1;
  namespace fs = std::filesystem;
  std::string name = expnam.empty() ? "contact_addon" : expnam;
  fs::path work = wrkdir;
  if (work.empty() && fs::path(name).has_parent_path()) work = fs::path(name).parent_path();
  name = fs::path(name).filename().string();
  work_ = work.empty() ? fs::current_path() : work;
  fs::path dir =
      outdir.empty() ? work : (fs::path(outdir).is_absolute() ? fs::path(outdir) : work / outdir);
  out_.open(dir / (name + ".out"), std::ios::trunc);  // a failed open is not an error (§1.6)
  const std::string banner =
      fmt::format("rollcontact CONTACT-compatible library, interface version {}", 2520);
  if (out_) out_ << banner << '\n';
  if (to_screen_) std::cout << banner << '\n';
  return true;
}

int Library::create(int ire, int module) {
  if (ire < 1 || ire > 999 || (module != 1 && module != 3)) {
    log(fmt::format("cntc_initialize: ire = {} or imodul = {} out of range (refused)", ire,
                    module));
    return -12;
  }
  std::lock_guard lock(mutex_);
  if (const auto it = elements_.find(ire); it != elements_.end()) {
    if (out_) {  // keeps its module, as CONTACT does
      out_ << fmt::format(
          "cntc_initialize: result element {} exists already (module {}); kept as it is\n", ire,
          it->second->module);
    }
    return 0;
  }
  if (static_cast<int>(elements_.size()) >= kMaxActiveElements) return -12;
  auto e = std::make_unique<ResultElement>();
  e->module = module;
  elements_.emplace(ire, std::move(e));
  return 0;
}

void Library::finalize(int ire) {
  bool last = false;
  {
    std::lock_guard lock(mutex_);
    if (!initialised_) return;
    if (elements_.erase(ire) == 0) {
      if (out_) out_ << fmt::format("cntc_finalize: result element {} does not exist\n", ire);
      return;
    }
    last = elements_.empty();
  }
  if (last) finalize_last();
}

void Library::finalize_last() {
  std::lock_guard lock(mutex_);
  if (!initialised_) return;
  elements_.clear();
  out_.close();
  initialised_ = false;
}

std::filesystem::path Library::working_folder() {
  std::lock_guard lock(mutex_);
  return work_.empty() ? std::filesystem::current_path() : work_;
}

void Library::log(const std::string& line) {
  std::lock_guard lock(mutex_);
  if (out_) out_ << line << '\n' << std::flush;
  if (to_screen_ || debug_level_ >= 1) std::cout << line << '\n';
}

int Library::check(int ire, int icp, Access access, int module) const {
  if (ire < 1 || ire > 999) return kBadIre;
  const bool m1 = module == 1;
  const bool is_patch = icp >= 1 && icp <= kMaxIcp;
  switch (access) {
    case Access::Module3:
      if (m1) return kNotInModule1;
      return icp >= 1 && icp <= kMaxIcp ? 0 : kBadIcp;
    case Access::Module1:  // no icp argument: the whole problem
      return m1 ? 0 : kNotInModule3;
    case Access::Module1Patch:
      if (!m1) return kNotInModule3;
      if (icp == -1) return kNeedsPatch;
      return is_patch ? 0 : kBadIcp;
    case Access::Module1Forces:
      if (!m1) return kNotInModule3;
      return icp == -1 || is_patch ? 0 : kBadIcp;
    case Access::Settings:
      if (m1) return icp == -1 ? 0 : kNoPatchAllowed;
      return is_patch ? 0 : kBadIcp;
    case Access::Results:
      if (icp == -1) return kNeedsPatch;
      return is_patch ? 0 : kBadIcp;
    case Access::Either:  // −1 is the whole wheel/rail problem; module 3 has problems 1..9 only
      return (m1 && icp == -1) || is_patch ? 0 : kBadIcp;
  }
  return kBadIcp;
}

int Library::check_patch_exists(int icp, Access access, const ResultElement& e) const {
  // Module 1: the patches are those of the last calculate (§1.3); getcontactlocation and
  // getglobalforces answer zeros for the others themselves (§5 checklist).
  if (e.module != 1 || icp < 1 || access == Access::Module1Patch || access == Access::Module1Forces)
    return 0;
  const Module1Problem* p = e.wheel_rail.get();
  const int patches = p != nullptr && p->result ? static_cast<int>(p->result->patches.size()) : 0;
  return icp <= patches ? 0 : kNoSuchPatch;
}

ResultElement* Library::element_or_create(int ire, int icp) {
  auto it = elements_.find(ire);
  if (it != elements_.end()) return it->second.get();
  if (static_cast<int>(elements_.size()) >= kMaxActiveElements) return nullptr;
  auto e = std::make_unique<ResultElement>();
  e->module = icp <= 0 ? 1 : 3;  // implicit creation (§1.3)
  return elements_.emplace(ire, std::move(e)).first->second.get();
}

Target Library::open(int ire, int icp, Access access, const char* routine, int* code) {
  initialize_first(0, "", "", "");  // implicit set-up (§1.3); returns when done already
  int status = 0;
  Target target;
  target.icp = icp;
  {
    std::lock_guard lock(mutex_);
    ResultElement* e = ire >= 1 && ire <= 999 ? element_or_create(ire, icp) : nullptr;
    status =
        e == nullptr ? (ire < 1 || ire > 999 ? kBadIre : -12) : check(ire, icp, access, e->module);
    if (status == 0) status = check_patch_exists(icp, access, *e);
    if (status == 0 && e->module == 3) {
      auto& slot = e->problems[static_cast<std::size_t>(icp)];
      if (!slot) slot = std::make_unique<Module3Problem>();
      slot->record.result_element = ire;
      slot->record.contact_problem = icp;
      target.m3 = slot.get();
    } else if (status == 0) {
      if (!e->wheel_rail) e->wheel_rail = std::make_unique<Module1Problem>();
      e->wheel_rail->record.result_element = ire;
      target.m1 = e->wheel_rail.get();
    }
  }
  if (status == kNoSuchPatch) {
    log(
        fmt::format("{}: ire = {} has no contact patch {} (code {}): the patches are those the "
                    "last cntc_calculate found",
                    routine, ire, icp, status));
    if (code != nullptr) *code = status;
  } else if (status != 0) {
    log(fmt::format("{}: access refused (code {}) for ire = {}, icp = {}: the routine is for {}",
                    routine, status, ire, icp, category_name(access)));
    if (code != nullptr) *code = status;
  }
  return target;
}

Target open_target(const int* ire, const int* icp, Access access, const char* routine, int* code) {
  if (ire == nullptr || icp == nullptr) {
    library().log(fmt::format("{}: null handle argument (refused)", routine));
    if (code != nullptr) *code = CNTC_err_icp;
    return {};
  }
  return library().open(*ire, *icp, access, routine, code);
}

void reject(const char* routine, const std::string& why) {
  library().log(fmt::format("{}: {} (refused, nothing changed)", routine, why));
}

Library& library() {
  static Library instance;
  return instance;
}

}  // namespace rollcontact::cntc
