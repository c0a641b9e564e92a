// Profile files (spec/inp-format.md §8.1-8.4): SIMPACK, Miniprof and plain tables, slices files,
// and the clean-up steps of §8.3 that the reader performs (mirroring, scaling, ordering).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "format/profiles/profile_points.hpp"
#include "format/profiles/profile_reader.hpp"
#include "format/profiles/profile_simpack.hpp"
#include "format/profiles/profile_slices.hpp"
#include "format/profiles/profile_table.hpp"
#include "rollcontact/errors.hpp"
#include "support/examples.hpp"
#include "support/files.hpp"

namespace rollcontact::format {
namespace {

using test_support::kExamples;

/// Writes `text` to the file `name` in `dir`; returns its path.
std::filesystem::path write_file(const test_support::ScratchDir& dir, const std::string& name,
                                 const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

const char* kSimpackRail = R"(! comment
header.begin
  version = 1
  type    = 0      ! 0 = rail
header.end
spline.begin
  units.len.f = 1.    ! metres
  shift.y     = 0.001
  mirror.y    = 1
  colour      = 3
  point.begin
   -0.020	0.002
    0.000   0.000  1.0
    0.020   0.002
  point.end
spline.end
this line is never read
)";

TEST(ProfileSimpack, KeysUnitsMirrorAndOrder) {
  std::vector<std::string> warnings;
  RawProfile raw = parse_simpack_profile(kSimpackRail, "r.prr", false, warnings);
  EXPECT_EQ(raw.y.size(), 3u);
  EXPECT_DOUBLE_EQ(raw.length_to_mm, 1000.0);
  EXPECT_EQ(raw.mirror_y_flag, 1);
  ASSERT_EQ(warnings.size(), 1u);  // unknown key 'colour'
  EXPECT_NE(warnings[0].find("colour"), std::string::npos);
  ProfileOptions options;  // MIRRORY=0: the file's mirror.y=1 mirrors
  const Profile p = finish_profile(raw, options, warnings);
  ASSERT_EQ(p.y.size(), 3u);
  // shift 1 mm, mirrored, scaled to mm, ordered by ascending y.
  EXPECT_DOUBLE_EQ(p.y[0], -21.0);
  EXPECT_DOUBLE_EQ(p.y[1], -1.0);
  EXPECT_DOUBLE_EQ(p.y[2], 19.0);
  EXPECT_DOUBLE_EQ(p.z[1], 0.0);
  EXPECT_DOUBLE_EQ(p.z[2], 2.0);
  // MIRRORY=1 in the .inp cancels the file's flag.
  options.mirror_y = 1;
  const Profile q = finish_profile(raw, options, warnings);
  EXPECT_DOUBLE_EQ(q.y[0], -19.0);
  EXPECT_NEAR(profile_chord_length(q), 2.0 * std::hypot(20.0, 2.0), 1e-9);
}

TEST(ProfileSimpack, Errors) {
  std::vector<std::string> w;
  std::string wheel_type = kSimpackRail;
  try {
    parse_simpack_profile(wheel_type, "w.prw", true, w);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "w.prw");
    EXPECT_EQ(e.line(), 4);
    EXPECT_NE(e.message().find("type"), std::string::npos);
  }
  std::string rotated = kSimpackRail;
  rotated.replace(rotated.find("colour      = 3"), 15, "rotate = 0.1");
  EXPECT_THROW(parse_simpack_profile(rotated, "r.prr", false, w), InputError);
  std::string bad_point = kSimpackRail;
  bad_point.replace(bad_point.find("0.020   0.002"), 13, "0.020   x");
  try {
    parse_simpack_profile(bad_point, "r.prr", false, w);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 14);
    EXPECT_EQ(e.offending(), "x");
  }
  std::string unterminated = kSimpackRail;
  unterminated.erase(unterminated.find("spline.end"));
  EXPECT_THROW(parse_simpack_profile(unterminated, "r.prr", false, w), InputError);
  EXPECT_THROW(parse_simpack_profile("1 2\n3 4\n", "r.prr", false, w), InputError);
}

TEST(ProfileTable, MiniprofHeaderColumnsAndComments) {
  const std::string text =
      "Filename=x.ban\nXYPoints=3\nXOffset=1.0\nColumnDef=A,X,Y,K\n\n"
      "\" 9 9 9 9\n"
      "0.1, -10.0, 3.0, 200\n"
      "0.2, 0.0, 0.0, 210   # comment\n"
      "0.3  1.0\n"
      "0.4, 10.0, 3.0, 220\n";
  std::vector<std::string> w;
  const RawProfile raw = parse_table_profile(text, "x.ban", true, w);
  ASSERT_EQ(raw.y.size(), 3u);
  EXPECT_DOUBLE_EQ(raw.y[0], -10.0);
  EXPECT_DOUBLE_EQ(raw.z[2], 3.0);
  EXPECT_DOUBLE_EQ(raw.shift_y, 1.0);
  ASSERT_EQ(raw.k_yield.size(), 3u);
  EXPECT_DOUBLE_EQ(raw.k_yield[1], 210.0);
  ASSERT_EQ(w.size(), 1u);  // the short line 9
  EXPECT_NE(w[0].find("x.ban:9"), std::string::npos);
}

TEST(ProfileTable, LegacyMiniprofHeaders) {
  // Issue 18: an old-style keyword header line, an empty offset value, a '#MINIWHEELPROF' start.
  std::vector<std::string> w;
  const RawProfile old_style =
      parse_table_profile("MINIPROF 101 148 1994 3 24\nXOffset=\nYOffset=0.5\n\n-10 1\n0 0\n10 1\n",
                          "old.ban", true, w);
  ASSERT_EQ(old_style.y.size(), 3u);
  EXPECT_DOUBLE_EQ(old_style.shift_y, 0.0);
  EXPECT_DOUBLE_EQ(old_style.shift_z, 0.5);
  const RawProfile wheel = parse_table_profile(
      "#MINIWHEELPROF\nColumnDef=X,Y\n\n30 -1\n0 0\n-30 -2\n", "w.whl", true, w);
  EXPECT_EQ(wheel.y.size(), 3u);
  // A header line that is neither a keyword line nor Key=Value is still an error.
  EXPECT_THROW(parse_table_profile("12abc\n\n0 0\n1 1\n", "bad.ban", true, w), InputError);
}

TEST(ProfileTable, PlainTableErrorsAndAutoMirrorZ) {
  std::vector<std::string> w;
  EXPECT_THROW(parse_table_profile("1 2\n", "p.txt", false, w), InputError);
  try {
    parse_table_profile("% c\n1 2\n3 four\n", "p.txt", false, w);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.offending(), "four");
  }
  // A rail given with z upwards (top of the head highest) is mirrored in z by auto-detection.
  RawProfile raw =
      parse_table_profile("-20 -2\n-10 -0.5\n0 0\n10 -0.5\n20 -2\n", "p.txt", false, w);
  ProfileOptions options;
  const Profile p = finish_profile(raw, options, w);
  EXPECT_DOUBLE_EQ(p.z.front(), 2.0);
  EXPECT_DOUBLE_EQ(p.z[2], 0.0);
  options.mirror_z = -1;  // as is
  EXPECT_DOUBLE_EQ(finish_profile(raw, options, w).z.front(), -2.0);
  // Wheels are ordered by descending y; SCALEYZ converts to mm.
  options.is_wheel = true;
  options.scale_yz = 10.0;
  const Profile q = finish_profile(raw, options, w);
  EXPECT_DOUBLE_EQ(q.y.front(), 200.0);
}

TEST(ProfileTable, ClosePointsAreRemoved) {
  std::vector<std::string> w;
  RawProfile raw = parse_table_profile("0 0\n0.00001 0\n1 0\n2 0\n", "p.txt", false, w);
  const Profile p = finish_profile(raw, ProfileOptions{}, w);
  EXPECT_EQ(p.y.size(), 3u);
}

TEST(ProfileFiles, ExampleProfiles) {
  REQUIRE_EXAMPLES();
  std::vector<std::string> w;
  ProfileOptions rail;
  const Profile prr = read_profile_file(kExamples / "MBench_UIC60_v3.prr", rail, w);
  EXPECT_EQ(prr.format, ProfileFormat::Simpack);
  EXPECT_EQ(prr.y.size(), 495u);
  const double chord = profile_chord_length(prr);
  EXPECT_GT(chord, 5.0);
  EXPECT_LT(chord, 500.0);
  // The Miniprof file comments out 19 of its 495 points with '"'.
  const Profile ban = read_profile_file(kExamples / "MBench_UIC60_v3.ban", rail, w);
  EXPECT_EQ(ban.format, ProfileFormat::Miniprof);
  EXPECT_EQ(ban.y.size(), 476u);
  ProfileOptions wheel;
  wheel.is_wheel = true;
  const Profile prw = read_profile_file(kExamples / "MBench_S1002_v3.prw", wheel, w);
  EXPECT_EQ(prw.y.size(), 399u);  // one of 400 points repeats its predecessor
  EXPECT_GT(prw.y.front(), prw.y.back());
  EXPECT_THROW(read_profile_file(kExamples / "MBench_S1002_v3.prw", rail, w), InputError);
  EXPECT_THROW(read_profile_file(kExamples / "missing.prr", rail, w), InputError);
}

TEST(ProfileSlices, WheelflatSlices) {
  REQUIRE_EXAMPLES();
  std::vector<std::string> w;
  ProfileOptions wheel;
  wheel.is_wheel = true;
  wheel.mirror_z = -1;
  const SlicedProfile sp = read_slices_file(kExamples / "S1002_flat.slcw", wheel, w);
  EXPECT_EQ(sp.slices.size(), 258u);
  EXPECT_EQ(sp.nfeat, 0);
  EXPECT_EQ(sp.u_intpol, 2);
  EXPECT_DOUBLE_EQ(sp.u.back(), 3.1224);
  EXPECT_NE(sp.slices.back().file.find("Wheel_section_207.txt"), std::string::npos);
}

TEST(ProfileSlices, FeaturesAndErrors) {
  const test_support::ScratchDir dir("rc_profile_slices");
  write_file(dir, "a.txt", "-20 2\n0 0\n20 2\n");
  write_file(dir, "b.txt", "-20 2.5\n0 0\n20 2.5\n");
  const auto ok =
      write_file(dir, "ok.slcs",
                 "! rail slices\n 10.0 1.0\n 2\n 3 1 1\n 1\n 0.0 'a.txt'\n 5.0 'b.txt'\n"
                 " 2\n 3\n 0.0 1 2 3\n 5.0 1.5 -1 3\n");
  std::vector<std::string> w;
  const SlicedProfile sp = read_slices_file(ok, ProfileOptions{}, w);
  ASSERT_EQ(sp.u.size(), 2u);
  EXPECT_DOUBLE_EQ(sp.u[1], 15.0);
  ASSERT_EQ(sp.kinks.size(), 1u);
  EXPECT_EQ(sp.kinks[0], 2);
  ASSERT_EQ(sp.features.size(), 2u);
  EXPECT_DOUBLE_EQ(sp.features[1][1], -1.0);

  const auto missing =
      write_file(dir, "missing.slcs", " 0 1\n 2\n 0\n 1\n 0.0 'a.txt'\n 1.0 'nope.txt'\n");
  try {
    read_slices_file(missing, ProfileOptions{}, w);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), missing.string());
    EXPECT_EQ(e.line(), 6);
    EXPECT_NE(e.message().find("'nope.txt'"), std::string::npos);
  }
  const auto decreasing =
      write_file(dir, "dec.slcs", " 0 1\n 2\n 0\n 1\n 1.0 'a.txt'\n 0.0 'b.txt'\n");
  EXPECT_THROW(read_slices_file(decreasing, ProfileOptions{}, w), InputError);
  const auto too_many = write_file(dir, "n.slcs", " 0 1\n 5000\n 0\n 1\n");
  EXPECT_THROW(read_slices_file(too_many, ProfileOptions{}, w), InputError);
}

}  // namespace
}  // namespace rollcontact::format
