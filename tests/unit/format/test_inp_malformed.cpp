// Malformed inputs (tests/data/malformed/*.inp): each must raise an InputError at the expected
// line with a distinctive message. The table is the sidecar of the corpus; every file in the
// folder must be listed.

#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <ostream>
#include <set>
#include <string>

#include "format/inp/inp_reader.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {
namespace {

const std::filesystem::path kMalformed =
    std::filesystem::path(ROLLCONTACT_TEST_DATA_DIR) / "malformed";

struct MalformedCase {
  const char* file;
  int line;              ///< expected InputError::line()
  const char* fragment;  ///< must occur in InputError::message()
  bool strict_files;     ///< read with InpReadOptions::missing_files_are_errors
};

constexpr MalformedCase kCases[] = {
    {"grid_mx_not_integer.inp", 11, "expected an integer for MX", false},
    {"truncated_b_array.inp", 14, "end of file while reading B(1..6) of the IBASE=1 block", false},
    {"digit_t_7.inp", 3, "digit T=7 is not a valid value (0..3)", false},
    {"poiss1_07.inp", 9, "POISS1 = 0.7 outside [0, 0.5]", false},
    {"poiss2_negative.inp", 9, "POISS2 = -0.1 outside [0, 0.5]", false},
    {"gg1_zero.inp", 9, "GG1 = 0 must be at least 1e-05", false},
    {"gg2_negative.inp", 9, "GG2 = -200 must be at least 1e-05", false},
    {"grid_too_large.inp", 11, "MX·MY = 2500000 exceeds 2 000 000", false},
    {"grid_mx_zero.inp", 11, "MX = 0 must be at least 1", false},
    {"grid_dx_tiny.inp", 11, "DX = 1e-09 outside [1e-8, 1e+08] mm", false},
    {"grid_dx_huge.inp", 14, "DX = 1000000000 outside [1e-8, 1e+08] mm", false},
    {"heat_heatcp_negative.inp", 11, "HEATCP1 = -450 must be positive", false},
    {"flxz_negative.inp", 10, "FLXZ = -1 must be positive", false},
    {"k0_zero.inp", 10, "K0_MF = 0 must be positive", false},
    {"memdst_negative.inp", 9, "MEMDST = -5 must be at least 0", false},
    {"letters_for_fn.inp", 7, "expected a real number for FN", false},
    {"maxgs_zero.inp", 6, "MAXGS = 0 outside 1..9999", false},
    {"maxin_too_large.inp", 6, "MAXIN = 1000000 outside 1..999999", false},
    {"maxout_too_large.inp", 6, "MAXOUT = 10000 outside 1..9999", false},
    {"eps_negative.inp", 6, "EPS = -0.0001 must be positive", false},
    {"fstat_ne_fkin.inp", 8, "needs FSTAT = FKIN", false},
    {"fkin_too_small.inp", 8, "FKIN = 1e-05 must be at least 0.0001", false},
    {"fx_above_1.inp", 7, "relative force |FX| = 1.5 exceeds 1", false},
    {"fxfy_above_1.inp", 7, "exceed 1", false},
    {"fn_zero.inp", 7, "FN = 0 must be positive", false},
    {"first_case_l1.inp", 4, "L=1 (keep friction) in the first case of result element 0", false},
    {"first_case_d0.inp", 4, "D=0 (keep grid) in the first case", false},
    {"first_case_s1.inp", 3, "S=1 uses stored subsurface points", false},
    {"d_without_z.inp", 4, "D=2 requires Z=1 or 2", false},
    {"switch_to_rolling_c0.inp", 16,
     "switching from T=1 to T=3 (rolling <-> non-rolling) requires C≠0", false},
    {"viscoelastic_t1.inp", 4, "M=1 (viscoelastic) requires T=3", false},
    {"heat_t1.inp", 5, "H=3 (temperature) requires T=3", false},
    {"l6_without_heat.inp", 4, "L=6 (temperature-dependent friction) requires H≥1", false},
    {"b2_non_hertzian.inp", 10, "B=2 requires a Hertzian IPOTCN", false},
    {"b4_with_n0.inp", 3, "B=4 (SDEC) requires N=1", false},
    {"b5_with_n1.inp", 3, "B=5 requires N=0", false},
    {"sdec_without_b4.inp", 10, "IPOTCN = -6 (SDEC) and B=4 go together", false},
    {"hertz2d_with_n0.inp", 10, "IPOTCN = -4 (2-D Hertz) requires N=1", false},
    {"hertz_negative_pen.inp", 10, "requires PEN ≥ 0", false},
    {"hertz_scale_zero.inp", 11, "SCALE = 0 must be positive", false},
    {"ipotcn_invalid.inp", 10, "IPOTCN = 5 is not a valid value (-6..-1, 1..4)", false},
    {"ipotcn_not_integer.inp", 10, "expected an integer for IPOTCN", false},
    {"ipotcn4_mx1.inp", 11, "MX = 1 must be at least 2", false},
    {"ibase_invalid.inp", 12, "IBASE = 4 is not a valid value (1, 2, 3, 9)", false},
    {"iplan_invalid.inp", 12, "IPLAN = 5 is not a valid value (1..4)", false},
    {"iplan3_limits.inp", 15, "IPLAN=3: XL1 = 1 exceeds XH1 = -1", false},
    {"ibase2_nn1.inp", 13, "NN = 1 outside 2..1000000", false},
    {"ibase2_rm_zero.inp", 13, "RM = 0: the x-radius of the IBASE=2 profile", false},
    {"ibase3_b8_zero.inp", 13, "B8 = 0: IBASE=3 divides by B7 and B8", false},
    {"flin2_negative.inp", 8, "FLIN2 = -0.05 must be at least 0", false},
    {"ibase9_truncated.inp", 43,
     "end of file while reading H(1..MX·MY) of the IBASE=9 block (300 of 361 values read)", false},
    {"missing_c9_file.inp", 9, "influence coefficient file 'nonexistent_inflcf.txt' not found",
     true},
    {"unterminated_quote.inp", 9, "unterminated quoted string", false},
    {"module_2.inp", 2, "module number 2 is not valid", false},
    // module_1.inp holds a module-3 case under a module-1 line: F=2 does not exist in module 1.
    {"module_1.inp", 4, "Z=2 keeps the rail profile, but none was read", false},
    {"reid_1000.inp", 2, "REID = 1000 outside 0..999", false},
    {"cpid_0.inp", 2, "CPID = 0 outside 1..9", false},
    {"word1_too_many_digits.inp", 3, "control word 1 (PBTNFS) has more than 7 digits", false},
    {"word1_negative.inp", 3, "must be a non-negative integer", false},
    {"word3_real.inp", 5, "expected an integer for control word 3 (XHGIAOWR)", false},
    {"polach_l5.inp", 4, "L=5 (Polach friction)", false},
    {"digit_c5.inp", 4, "digit C=5 is not a valid value (0, 1, 2, 3, 4, 9)", false},
    {"digit_e5.inp", 4, "digit E=5 is not a valid value (0, 1, 2, 3, 9)", false},
    {"digit_v1.inp", 4, "digit V=1 is not a valid value (0, 3)", false},
    {"digit_h2.inp", 5, "digit H=2 is not a valid value (0, 1, 3)", false},
    {"digit_o6.inp", 5, "digit O=6 is not a valid value (0..5)", false},
    {"m2_invalid.inp", 4, "second integer of control word 2 (10*GAPWGT + M2)", false},
    {"eof_after_r0.inp", 14,
     "end of file where the control words of the case after case 1 were expected", false},
    {"comments_only.inp", 4, "no module line found", false},
    {"truncated_mid_group.inp", 12,
     "end of file while reading the IPOTCN=1 line (MX MY XL YL DX DY) (YL missing)", false},
    {"e9_truncated.inp", 15, "end of file while reading the E=9 extra rigid slip", false},
    {"isubs_invalid.inp", 15, "ISUBS = 4 is not a valid value", false},
    {"subsurface_dz_zero.inp", 16, "DZ = 0 must be positive", false},
    {"subsurface_11_blocks.inp", 35, "more than 10 subsurface blocks", false},
    {"subsurface_letters.inp", 18,
     "expected a real number for value 3 of the NZ z-values of subsurface block 1 (ISUBS=5)",
     false},
    {"s2_without_blocks.inp", 15, "S=2 uses stored subsurface points", false},
    {"keep_c0_grid_larger.inp", 20,
     "grid 25x19 is larger than the 19x19 grid of the stored influence coefficients", false},
    {"keep_c0_dx_changed.inp", 20, "element size DX, DY", false},
    {"p0_d2_half_element.inp", 20, "must be a whole number of elements", false},
    {"p0_d2_dx_changed.inp", 20, "must equal the previous", false},
    {"l1_v_changes.inp", 16, "L=1 (keep friction) while V changes from 0 to 3", false},
    {"dq_below_eps.inp", 9, "DQ = 0 must be at least EPS = 0.0001", false},
    {"dq_with_degrees.inp", 9, "expected a real number for DQ", false},
    {"h1_without_params.inp", 5, "H=1 uses stored heat parameters", false},
    {"betapl_above_1.inp", 14, "BETAPL = 1.5 outside [0, 1]", false},
    {"viscoelastic_chi.inp", 4, "M=1 (viscoelastic) requires rolling direction CHI = 0", false},
    {"c4_variant_5.inp", 9, "VARIANT = 5 outside 1..4", false},
    {"array_51_words.inp", 28, "more than 50 values on one line of", false},
    {"z1_first_case.inp", 4, "Z=1 uses the stored undeformed distance, but no IBASE block was read",
     false},
    // Module 1 (wheel/rail); profiles in malformed/profiles/.
    {"m1_missing_profile.inp", 11, "rail profile file 'profiles/nonexistent.prr' not found", false},
    {"m1_scaleyz_too_large.inp", 14, "outside 5..500 mm (check SCALEYZ = 100)", false},
    {"m1_digit_c1_3.inp", 3, "digit C1=3 is not a valid value (0, 1, 4, 5)", false},
    {"m1_f1_with_n0.inp", 3, "F=1 (prescribed FX_WS) requires N=1", false},
    {"m1_dsep_below_dcomb.inp", 9, "D_SEP = 3 must be at least D_COMB = 4", false},
    {"m1_dqrel_out_of_range.inp", 9, "DQREL = 20 outside [5e-07, 10]", false},
    {"m1_truncated_wheelset.inp", 15,
     "end of file while reading the wheelset position line (S_WS Y_WS FZ ROLL YAW PITCH)", false},
    {"m1_first_case_z0.inp", 4,
     "Z=0 keeps the rail profile, but none was read for result element 0", false},
    {"m1_digit_b2.inp", 3, "digit B=2 is not a valid value (0, 1, 5, 6)", false},
    {"m1_digit_e9.inp", 4, "digit E=9 is not a valid value (0..5)", false},
    {"m1_digit_m8.inp", 4, "digit M=8 is not a valid value (0..7)", false},
    {"m1_digit_i9.inp", 5, "digit I=9 is not a valid value (0..3)", false},
    {"m1_digit_r9.inp", 5, "digit R=9 is not a valid value (0..3)", false},
    {"m1_nomradw_zero.inp", 13, "NOMRADW = 0 must be at least 0.001", false},
    {"m1_mirrory_2.inp", 11, "MIRRORY = 2 outside -1..1", false},
    {"m1_slcs_with_gaught.inp", 11, "a rail slices file (.slcs) requires GAUGHT ≤ 0", false},
    {"m1_nvf_not_increasing.inp", 9, "friction control points must be strictly increasing", false},
    {"m1_e0_n_changes.inp", 19, "E=0 (keep wheelset) while N changes from 1 to 0", false},
    {"m1_prfopt_bad_kinklow.inp", 12, "expected an angle for KINKLOW", false},
    {"m1_viscoelastic_backwards.inp", 17,
     "M=1 (viscoelastic) requires rolling in +x (CHI = 0): VS = -2000 mm/s", false},
};

// gtest prints the file name instead of the bytes of the struct.
void PrintTo(const MalformedCase& c, std::ostream* os) {
  *os << c.file;
}

class InpMalformed : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(InpMalformed, RaisesInputErrorAtLine) {
  const MalformedCase& c = GetParam();
  const std::filesystem::path path = kMalformed / c.file;
  ASSERT_TRUE(std::filesystem::is_regular_file(path)) << path;
  InpReadOptions options;
  options.missing_files_are_errors = c.strict_files;
  try {
    read_inp_file(path, options);
    FAIL() << c.file << ": expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path.string());
    EXPECT_EQ(e.line(), c.line) << e.what();
    EXPECT_NE(e.message().find(c.fragment), std::string::npos)
        << "message: " << e.message() << "\nexpected fragment: " << c.fragment;
    const std::string what = e.what();
    EXPECT_NE(what.find(path.string() + ":" + std::to_string(c.line) + ": "), std::string::npos)
        << what;
  }
}

std::string case_name(const ::testing::TestParamInfo<MalformedCase>& info) {
  std::string name = info.param.file;
  name = name.substr(0, name.find('.'));
  for (char& ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, InpMalformed, ::testing::ValuesIn(kCases), case_name);

TEST(InpMalformedCorpus, EveryFileIsListedAndCorpusIsLarge) {
  std::set<std::string> listed;
  for (const auto& c : kCases) listed.insert(c.file);
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kMalformed)) {
    if (entry.path().extension() != ".inp") continue;
    ++files;
    EXPECT_TRUE(listed.count(entry.path().filename().string()))
        << entry.path() << " has no expectation in kCases";
  }
  EXPECT_EQ(files, listed.size());
  EXPECT_GE(files, 40u);
}

}  // namespace
}  // namespace rollcontact::format
