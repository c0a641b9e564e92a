#pragma once
// Where the bodies may touch and how far apart their surfaces are before deformation
// (spec/physics.md §2, §4, §8). Lengths in mm, curvatures in 1/mm.
//
// Both descriptions keep the numbered forms of the spec (IPOTCN, IBASE, IPLAN): they are the
// documented encodings of a rectangle or a Hertzian area and of a gap function, each with its
// own list of values, not control digits; docs/decisions.md says why they are not variants yet.

#include <array>
#include <vector>

namespace rollcontact::model {

/// The potential contact area: a rectangle of MX × MY elements, or an area derived from the Hertz
/// solution. The four values keep their spec meaning:
///  form  1: XL YL DX DY       2: XL YL XH YH       3: XC1 YC1 DX DY     4: XC1 YC1 XCM YCM
///  form -1: A1 B1 SCALE       -2: A1 AOB SCALE     -3: AA BB SCALE      -4: A1 BB SCALE
///  form -5: AA BB SCALE       -6: AA BNEG BPOS SCALE
/// (curvatures A1, B1 in 1/mm, semi-axes in mm; SCALE = potential area / Hertz area).
struct PotentialContact {
  int ipotcn = 1;  ///< the form (spec inp-format.md §4.2, IPOTCN)
  int mx = 1, my = 1;
  std::array<double, 4> values{};
  bool hertzian() const noexcept { return ipotcn < 0; }
};

/// Undeformed distance h(x, y) [mm] on a rectangular potential contact (spec physics.md §4).
struct UndeformedDistance {
  int ibase = 1;               ///< 1 quadratic, 2 tabulated profile, 3 sines, 9 per element
  int iplan = 1;               ///< 1 unrestricted, 2 quadratic planform, 3 two rectangles
  std::vector<double> coeffs;  ///< IBASE 1: B1..B6; 3: B1..B8; 2: profile samples B(1..NN)
  double xm = 0.0, rm = 0.0, y1 = 0.0, dy1 = 0.0;  ///< IBASE 2 [mm]
  std::vector<double> values;                      ///< IBASE 9: h per element [mm], ix fastest
  std::vector<double> planform;       ///< IPLAN 2: PL1..6; IPLAN 3: XL1 XH1 YL1 YH1 XL2 XH2 YL2 YH2
                                      ///< IPLAN 4: XL XH YL YH per patch (4*npatch values)
  int npatch = 0;                     ///< IPLAN 4 (experimental): number of patches
  std::vector<double> patch_factors;  ///< IPLAN 4: f12 f13 ... f23 ... (npatch*(npatch-1)/2)
};

/// One block of subsurface points at which stresses are wanted (spec/inp-format.md §6).
struct SubsurfaceBlock {
  int isubs = 1;  ///< 1/5 all elements, 2/6 regular column/row selection, 3/7 lists, 9 points
  int ixl = 1, ixinc = 1, ixh = 1;  ///< ISUBS 2,6: 1-based column range and step
  int iyl = 1, iyinc = 1, iyh = 1;  ///< ISUBS 2,6: 1-based row range and step
  std::vector<int> ix, iy;          ///< ISUBS 3,7: 1-based columns / rows (sorted, unique)
  double zl = 0.0, dz = 0.0;        ///< ISUBS 1,2,3: z_k = zl + (k-1) dz [mm]
  std::vector<double> x, y;         ///< ISUBS 9: coordinates [mm], sorted ascending
  std::vector<double> z;            ///< all ISUBS: depths [mm] (z >= 0 in body 1), ascending
};

}  // namespace rollcontact::model
