#pragma once
// Small 3-D vectors and rotations of the wheel/rail geometry, and the frames of spec/physics.md
// §13.2: track (x along the track, y lateral to the field side, z down) and wheelset (origin on
// the axle at the wheelset centre, y along the axle). Everything in mm and rad.

#include <cmath>

namespace rollcontact::wheelrail {

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
};
inline Vec3 operator+(Vec3 a, Vec3 b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3 operator-(Vec3 a, Vec3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3 operator*(double s, Vec3 a) {
  return {s * a.x, s * a.y, s * a.z};
}
inline double dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// A rotation matrix, rows r[i].
struct Mat3 {
  double r[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Vec3 operator*(Vec3 v) const {
    return {r[0][0] * v.x + r[0][1] * v.y + r[0][2] * v.z,
            r[1][0] * v.x + r[1][1] * v.y + r[1][2] * v.z,
            r[2][0] * v.x + r[2][1] * v.y + r[2][2] * v.z};
  }
  /// Rᵀ v (the inverse rotation).
  Vec3 transposed_times(Vec3 v) const {
    return {r[0][0] * v.x + r[1][0] * v.y + r[2][0] * v.z,
            r[0][1] * v.x + r[1][1] * v.y + r[2][1] * v.z,
            r[0][2] * v.x + r[1][2] * v.y + r[2][2] * v.z};
  }
};

/// The product a·b of two rotations.
inline Mat3 product(const Mat3& a, const Mat3& b) {
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      m.r[i][j] = a.r[i][0] * b.r[0][j] + a.r[i][1] * b.r[1][j] + a.r[i][2] * b.r[2][j];
  return m;
}

/// R_x(roll) · R_z(yaw): the wheelset's orientation in the track (pitch is the wheel's own
/// rotation about its axle and does not change the surface of a round wheel).
inline Mat3 roll_yaw_rotation(double roll, double yaw) {
  const double cr = std::cos(roll), sr = std::sin(roll), cy = std::cos(yaw), sy = std::sin(yaw);
  Mat3 m;
  m.r[0][0] = cy, m.r[0][1] = -sy, m.r[0][2] = 0;
  m.r[1][0] = cr * sy, m.r[1][1] = cr * cy, m.r[1][2] = -sr;
  m.r[2][0] = sr * sy, m.r[2][1] = sr * cy, m.r[2][2] = cr;
  return m;
}

}  // namespace rollcontact::wheelrail
