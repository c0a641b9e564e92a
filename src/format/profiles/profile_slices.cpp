#include "format/profiles/profile_slices.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <system_error>

#include "format/profiles/profile_reader.hpp"
#include "format/profiles/profile_text.hpp"
#include "format/text/inp_checks.hpp"
#include "format/text/inp_stream.hpp"

namespace rollcontact::format {

namespace {

constexpr FieldKind kInt = FieldKind::integer;
constexpr FieldKind kReal = FieldKind::real;
constexpr int kMaxSlices = 4999;
constexpr double kMinSliceDistance = 0.001;  // U_SLC spacing [file units]
constexpr double kMaxFeaturePosition = 1e6;  // [mm]

/// The slices file with `!` and `"` comments removed (the .inp lexer handles `%` itself), so
/// that InpStream can read it with the lexical rules of spec §1 and the original line numbers.
std::string without_extra_comments(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const std::string& line : split_lines(text)) {
    out.append(strip_comment(line, "!\"")).push_back('\n');
  }
  return out;
}

}  // namespace

SlicedProfile read_slices_file(const std::filesystem::path& path, const ProfileOptions& options,
                               std::vector<std::string>& warnings) {
  SlicedProfile sp;
  sp.file = path.string();
  InpStream in(without_extra_comments(read_text_file(path)), sp.file);
  const char* u_name = options.is_wheel ? "TH" : "U";

  const GroupValues h1 =
      in.read_group({{"U_OFFSET", kReal}, {"U_SCALE", kReal}}, "the line U_OFFSET U_SCALE");
  sp.u_offset = h1.real(0);
  sp.u_scale = h1.real(1);
  if (sp.u_scale == 0.0) in.fail(h1.line(1), fmt::format("{}_SCALE must not be 0", u_name));
  const GroupValues h2 = in.read_group({{"NSLC", kInt}}, "the line NSLC");
  require_int_range(in, h2.line(0), "NSLC", h2.integer(0), 1, kMaxSlices);
  const auto nslc = static_cast<std::size_t>(h2.integer(0));
  const GroupValues h3 =
      in.read_group({{"NFEAT", kInt}, {"NKINK", kInt, true}, {"NACCEL", kInt, true}},
                    "the line NFEAT {NKINK {NACCEL}}");
  sp.nfeat = h3.integer(0);
  sp.nkink = h3.has(1) ? h3.integer(1) : 0;
  sp.naccel = h3.has(2) ? h3.integer(2) : 0;
  require_int_range(in, h3.line(0), "NFEAT", sp.nfeat, 0, 9999);
  require_int_range(in, h3.line(1), "NKINK", sp.nkink, 0, std::max(0, sp.nfeat));
  require_int_range(in, h3.line(2), "NACCEL", sp.naccel, 0, std::max(0, sp.nfeat));
  const GroupValues h4 =
      in.read_group({{"U_INTPOL", kInt}, {"PERTURB", kInt, true}}, "the line U_INTPOL {PERTURB}");
  require_int_range(in, h4.line(0), "U_INTPOL", h4.integer(0), 1, 2);
  sp.u_intpol = h4.integer(0);

  const std::filesystem::path folder = path.parent_path();
  std::vector<double> u_slc(nslc);
  sp.u.resize(nslc);
  sp.slices.reserve(nslc);
  for (std::size_t k = 0; k < nslc; ++k) {
    const GroupValues g = in.read_group({{"U_SLC", kReal}, {"FNAME", FieldKind::string}},
                                        fmt::format("slice {} (U_SLC 'FNAME')", k + 1));
    u_slc[k] = g.real(0);
    if (k > 0 && !(u_slc[k] >= u_slc[k - 1] + kMinSliceDistance)) {
      in.fail(g.line(0),
              fmt::format("slice positions must increase by at least {}: slice {} at {} follows {}",
                          kMinSliceDistance, k + 1, u_slc[k], u_slc[k - 1]));
    }
    sp.u[k] = sp.u_scale * (sp.u_offset + u_slc[k]);
    if (options.is_wheel && std::abs(sp.u[k]) > 1.5 * std::numbers::pi + 1e-12) {
      in.fail(g.line(0),
              fmt::format("wheel slice angle {} rad outside [-1.5 pi, 1.5 pi]", sp.u[k]));
    }
    const std::filesystem::path name(g.text(1));
    const std::filesystem::path slice_path =
        (name.is_absolute() ? name : folder / name).lexically_normal();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(slice_path, ec)) {
      in.fail(g.line(1), fmt::format("profile file '{}' of slice {} not found (looked for {})",
                                     g.text(1), k + 1, slice_path.string()));
    }
    if (profile_format_of(slice_path) == ProfileFormat::Slices) {
      in.fail(g.line(1), "a slice must be a profile file, not another slices file", g.text(1));
    }
    sp.slices.push_back(read_profile_file(slice_path, options, warnings));
  }
  if (sp.nkink > 0) {
    sp.kinks = in.read_integers(static_cast<std::size_t>(sp.nkink), "the NKINK kink features");
  }
  if (sp.naccel > 0) {
    sp.accels =
        in.read_integers(static_cast<std::size_t>(sp.naccel), "the NACCEL acceleration features");
  }
  if (sp.nfeat > 1) {
    const auto nf = static_cast<std::size_t>(sp.nfeat);
    sp.features.resize(nslc);
    for (std::size_t k = 0; k < nslc; ++k) {
      const auto row = in.read_reals(nf + 1, fmt::format("U_SLC S_F(1..NFEAT) of slice {}", k + 1));
      if (std::abs(row[0] - u_slc[k]) > 1e-6 * std::max(1.0, std::abs(u_slc[k]))) {
        in.fail(in.last_line(), fmt::format("feature line of slice {} starts with {} instead of "
                                            "the slice position {}",
                                            k + 1, row[0], u_slc[k]));
      }
      sp.features[k].assign(row.begin() + 1, row.end());
      for (const double f : sp.features[k]) {
        if (f > kMaxFeaturePosition) {
          in.fail(in.last_line(),
                  fmt::format("feature position {} of slice {} exceeds 1e6", f, k + 1));
        }
      }
    }
  }
  return sp;
}

bool has_slices_extension(const std::filesystem::path& path, bool is_wheel) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == (is_wheel ? ".slcw" : ".slcs");
}

}  // namespace rollcontact::format
