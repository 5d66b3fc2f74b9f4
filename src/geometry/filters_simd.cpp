// insphere_filter4 and orient3d_filter4: detail::lifted_filter<false> and orient3d_filter
// (filters.hpp) on four tests at once, one per lane of a vector of doubles. Every lane goes
// through the same IEEE binary64 operations, round to nearest, in the same order as the
// scalar filter (the build's -ffp-contract=off keeps every product and sum apart, as fp.hpp
// requires), so its answer is the scalar filter's bit for bit: tests/cpu/predicates.cpp
// (FilterBounds.SimdFiltersAnswerAsTheScalarFilters) holds them together.
//
// Why a second text of the same arithmetic instead of one template over the number type:
// that template was tried (session 51), and nvcc then inlined differently in the exact
// kernels that call the scalar filter (6 to 25 kernels' machine code changed, some by
// ±20 % in size, the star splaying's proofs and death certificates among them) with no
// device to measure what that costs. The scalar filter stays as it is.
#include "geometry/filters_simd.hpp"

#include "geometry/filter_bounds.hpp"
#include "geometry/filters.hpp"

namespace gdel::geom {

namespace {
typedef double V4 __attribute__((vector_size(32)));
// As fp::abs and x > y ? x : y, lane by lane.
inline __attribute__((always_inline)) V4 vabs(V4 a) {
  const V4 zero = {0.0, 0.0, 0.0, 0.0};
  return a < zero ? -a : a;
}
inline __attribute__((always_inline)) V4 vgreater(V4 a, V4 b) { return a > b ? a : b; }
}  // namespace

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
__attribute__((target_clones("avx2", "default")))
#endif
void orient3d_filter4(const double* const (*t)[3], const double* d, int n, int* out) {
  // Lanes past n repeat lane 0 (their answers are not written).
  const int k1 = n > 1 ? 1 : 0, k2 = n > 2 ? 2 : 0, k3 = n > 3 ? 3 : 0;
  V4 x[3], y[3], z[3];  // the points a, b, c of each lane
  for (int i = 0; i < 3; ++i) {
    x[i] = V4{t[0][i][0], t[k1][i][0], t[k2][i][0], t[k3][i][0]};
    y[i] = V4{t[0][i][1], t[k1][i][1], t[k2][i][1], t[k3][i][1]};
    z[i] = V4{t[0][i][2], t[k1][i][2], t[k2][i][2], t[k3][i][2]};
  }
  const V4 ux = x[1] - x[0], uy = y[1] - y[0], uz = z[1] - z[0];
  const V4 vx = x[2] - x[0], vy = y[2] - y[0], vz = z[2] - z[0];
  const V4 wx = d[0] - x[0], wy = d[1] - y[0], wz = d[2] - z[0];
  const V4 mx = vy * wz - vz * wy;
  const V4 my = vz * wx - vx * wz;
  const V4 mz = vx * wy - vy * wx;
  const V4 det = (ux * mx + uy * my) + uz * mz;
  const V4 px = vabs(vy) * vabs(wz) + vabs(vz) * vabs(wy);
  const V4 py = vabs(vz) * vabs(wx) + vabs(vx) * vabs(wz);
  const V4 pz = vabs(vx) * vabs(wy) + vabs(vy) * vabs(wx);
  const V4 perm = (vabs(ux) * px + vabs(uy) * py) + vabs(uz) * pz;
  for (int k = 0; k < n; ++k)
    out[k] = detail::filter_decide(det[k], perm[k], bounds::kOrient3dThreshold, bounds::kOrient3dRoundings);
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
__attribute__((target_clones("avx2", "default")))
#endif
void insphere_filter4(const double* const (*t)[4], const double* e, int n, int* out) {
  // Lanes past n repeat lane 0 (their answers are not written).
  const int k1 = n > 1 ? 1 : 0, k2 = n > 2 ? 2 : 0, k3 = n > 3 ? 3 : 0;
  V4 x[4], y[4], z[4], l[4], ax[4], ay[4], az[4];
  for (int i = 0; i < 4; ++i) {
    const double *a = t[0][i], *b = t[k1][i], *c = t[k2][i], *d = t[k3][i];
    x[i] = V4{a[0], b[0], c[0], d[0]} - e[0];
    y[i] = V4{a[1], b[1], c[1], d[1]} - e[1];
    z[i] = V4{a[2], b[2], c[2], d[2]} - e[2];
    ax[i] = vabs(x[i]);
    ay[i] = vabs(y[i]);
    az[i] = vabs(z[i]);
    l[i] = (x[i] * x[i] + y[i] * y[i]) + z[i] * z[i];  // = la[i] (no weights)
  }
  V4 m[4][4];
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) m[i][j] = x[i] * y[j] - x[j] * y[i];
  auto minor3 = [&](int i, int j, int k) { return (z[i] * m[j][k] - z[j] * m[i][k]) + z[k] * m[i][j]; };
  const V4 m0 = minor3(1, 2, 3), m1 = minor3(0, 2, 3), m2 = minor3(0, 1, 3), m3 = minor3(0, 1, 2);
  const V4 det = (l[0] * m0 - l[1] * m1) + (l[2] * m2 - l[3] * m3);
  const V4 zero = {0.0, 0.0, 0.0, 0.0};
  V4 X = zero, Y = zero, Z = zero, L = zero;
  for (int i = 0; i < 4; ++i) {
    X = vgreater(ax[i], X);
    Y = vgreater(ay[i], Y);
    Z = vgreater(az[i], Z);
    L = vgreater(l[i], L);
  }
  const V4 qb = X * Y + X * Y;
  const V4 tb = Z * qb;
  const V4 pb = (tb + tb) + tb;
  const V4 ub = L * pb;
  const V4 quick = (ub + ub) + (ub + ub);
  constexpr double threshold = bounds::kInsphereThreshold;
  constexpr int roundings = bounds::kInsphereRoundings;
  bool open = false;
  for (int k = 0; k < n; ++k) {
    out[k] = detail::filter_decide(det[k], quick[k], threshold, roundings);
    open |= out[k] == kUncertain;
  }
  if (!open) return;
  V4 q[4][4];
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) q[i][j] = ax[i] * ay[j] + ax[j] * ay[i];
  auto perm3 = [&](int i, int j, int k) { return (az[i] * q[j][k] + az[j] * q[i][k]) + az[k] * q[i][j]; };
  const V4 p0 = perm3(1, 2, 3), p1 = perm3(0, 2, 3), p2 = perm3(0, 1, 3), p3 = perm3(0, 1, 2);
  const V4 perm = (l[0] * p0 + l[1] * p1) + (l[2] * p2 + l[3] * p3);
  for (int k = 0; k < n; ++k)
    if (out[k] == kUncertain) out[k] = detail::filter_decide(det[k], perm[k], threshold, roundings);
}

}  // namespace gdel::geom
