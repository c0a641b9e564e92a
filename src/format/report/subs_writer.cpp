#include "format/report/subs_writer.hpp"

#include <fmt/format.h>

#include <string_view>

#include "format/report/number_format.hpp"
#include "format/text/atomic_file.hpp"

namespace rollcontact::format {

namespace {

// Column titles as CONTACT writes them (its Matlab scripts read the file by position).
constexpr std::string_view kTitles1 =
    "%    X           Y           Z          UX          UY          UZ        SIGHYD      SIGVM";
constexpr std::string_view kTitles2 =
    "       SIGXX       SIGXY       SIGXZ       SIGYY       SIGYZ"
    "       SIGZZ";

void append_block(std::string& out, const SubsurfaceResult& r, bool tensor) {
  const std::size_t columns = tensor ? 14 : 8;
  out += "%   NX          NY          NZ";
  for (std::size_t c = 3; c < columns; ++c) out += "           -";
  out += '\n';
  out += fortran_i(static_cast<long long>(r.x.size()), 6) +
         fortran_i(static_cast<long long>(r.y.size()), 12) +
         fortran_i(static_cast<long long>(r.z.size()), 12) + std::string(6, ' ');
  for (std::size_t c = 3; c < columns; ++c) out += "   0.000    ";
  out += '\n';
  out += kTitles1;
  if (tensor) out += kTitles2;
  out += '\n';
  const std::size_t nx = r.x.size(), ny = r.y.size();
  for (std::size_t k = 0; k < r.size(); ++k) {
    const double row[14] = {r.x[k % nx], r.y[(k / nx) % ny], r.z[k / (nx * ny)], r.ux[k],  r.uy[k],
                            r.uz[k],     r.sighyd[k],        r.sigvm[k],         r.sxx[k], r.sxy[k],
                            r.sxz[k],    r.syy[k],           r.syz[k],           r.szz[k]};
    for (std::size_t c = 0; c < columns; ++c) append_fmt_sig(out, 12, 6, 5, row[c]);
    out += '\n';
  }
}

std::string format_blocks(const std::vector<SubsurfaceResult>& blocks, bool tensor) {
  std::string out;
  for (const SubsurfaceResult& r : blocks) append_block(out, r, tensor);
  return out;
}

}  // namespace

std::string format_subs(const CaseRecord& problem, const Solution& solution) {
  return format_blocks(solution.subsurface, problem.subsurface.matfil >= 2);
}

std::filesystem::path write_subs_file(const std::filesystem::path& output_stem,
                                      const CaseRecord& problem, const Solution& solution) {
  if (problem.digits.s < 1 || problem.subsurface.matfil < 1 || solution.subsurface.empty()) {
    return {};
  }
  std::filesystem::path path = output_stem;
  path += fmt::format(".{:04d}.subs", problem.case_number);
  write_file_atomically(path, format_subs(problem, solution));
  return path;
}

std::vector<std::filesystem::path> write_wheelrail_subs_files(
    const std::filesystem::path& output_stem, const WheelRailRecord& record,
    const CaseRecord& identity, const WheelRailSolution& solution) {
  std::vector<std::filesystem::path> written;
  if (record.digits.s < 1 || record.subsurface.matfil < 1) return written;
  for (std::size_t k = 0; k < solution.patches.size(); ++k) {
    const Solution& patch = solution.patches[k].solution;
    if (patch.subsurface.empty()) continue;
    std::filesystem::path path = output_stem;
    path += fmt::format(".{:04d}{}.subs", identity.case_number, static_cast<char>('a' + k % 26));
    write_file_atomically(path, format_blocks(patch.subsurface, record.subsurface.matfil >= 2));
    written.push_back(path);
  }
  return written;
}

}  // namespace rollcontact::format
