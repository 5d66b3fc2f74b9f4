// Floating-point filters of the three main predicates (translated formulations, which keep
// the permanent small for points far from the origin). Constants and their derivation:
// filter_bounds.hpp. Each returns -1 or +1 when the sign is certain, kUncertain otherwise.
#pragma once

#include "core/macros.hpp"
#include "geometry/filter_bounds.hpp"
#include "geometry/fp.hpp"
#include "geometry/minors.hpp"

namespace gdel::geom {

namespace detail {
GDEL_HD GDEL_FORCEINLINE int filter_decide(double det, double perm, double threshold, int n) {
  if (!(perm >= threshold && perm <= bounds::kMaxFinite)) return kUncertain;
  const double err = fp::mul(bounds::coefficient(n), perm);
  if (det > err) return 1;
  if (-det > err) return -1;
  return kUncertain;
}
}  // namespace detail

// What a filter evaluated, for the small-integer stage (predicates.hpp): its determinant
// as computed, and the largest absolute coordinate difference it formed. To be read only
// when the filter answered kUncertain.
struct FilterValue {
  double det = 0;
  double span = 0;
};

// orient3d(a,b,c,d) = sign det[b-a, c-a, d-a]  (N = 8, T = 2^-815).
GDEL_HD inline int orient3d_filter(const double* a, const double* b, const double* c,
                                   const double* d, FilterValue* out = nullptr) {
  using namespace fp;
  const double ux = sub(b[0], a[0]), uy = sub(b[1], a[1]), uz = sub(b[2], a[2]);
  const double vx = sub(c[0], a[0]), vy = sub(c[1], a[1]), vz = sub(c[2], a[2]);
  const double wx = sub(d[0], a[0]), wy = sub(d[1], a[1]), wz = sub(d[2], a[2]);
  // det = ux (vy wz - vz wy) + uy (vz wx - vx wz) + uz (vx wy - vy wx)
  const double mx = sub(mul(vy, wz), mul(vz, wy));
  const double my = sub(mul(vz, wx), mul(vx, wz));
  const double mz = sub(mul(vx, wy), mul(vy, wx));
  const double det = add(add(mul(ux, mx), mul(uy, my)), mul(uz, mz));
  const double px = add(mul(abs(vy), abs(wz)), mul(abs(vz), abs(wy)));
  const double py = add(mul(abs(vz), abs(wx)), mul(abs(vx), abs(wz)));
  const double pz = add(mul(abs(vx), abs(wy)), mul(abs(vy), abs(wx)));
  const double perm = add(add(mul(abs(ux), px), mul(abs(uy), py)), mul(abs(uz), pz));
  const int s = detail::filter_decide(det, perm, bounds::kOrient3dThreshold, bounds::kOrient3dRoundings);
  if (out && s == kUncertain) {
    auto mx3 = [](double x, double y, double z) {
      const double m = abs(x) > abs(y) ? abs(x) : abs(y);
      return m > abs(z) ? m : abs(z);
    };
    const double su = mx3(ux, uy, uz), sv = mx3(vx, vy, vz), sw = mx3(wx, wy, wz);
    const double m = su > sv ? su : sv;
    *out = {det, m > sw ? m : sw};
  }
  return s;
}

namespace detail {

// Shared body of insphere_filter / power_filter:
//   value = -det[ (a-e, l_a); (b-e, l_b); (c-e, l_c); (d-e, l_d) ],
//   l_p = |p - e|^2 - (w_p - w_e)   (w ignored when !Weighted)
//         = l_a M(bcd) - l_b M(acd) + l_c M(abd) - l_d M(abc),  M = 3x3 det of differences.
template <bool Weighted>
GDEL_HD GDEL_FORCEINLINE int lifted_filter(const double* const* p, const double* w, FilterValue* out = nullptr) {
  using namespace fp;
  const double* e = p[4];
  double x[4], y[4], z[4], l[4], ax[4], ay[4], az[4], la[4];
  for (int i = 0; i < 4; ++i) {
    x[i] = sub(p[i][0], e[0]);
    y[i] = sub(p[i][1], e[1]);
    z[i] = sub(p[i][2], e[2]);
    ax[i] = abs(x[i]);
    ay[i] = abs(y[i]);
    az[i] = abs(z[i]);
    const double s = add(add(mul(x[i], x[i]), mul(y[i], y[i])), mul(z[i], z[i]));
    if constexpr (Weighted) {
      const double dw = sub(w[i], w[4]);
      l[i] = sub(s, dw);
      la[i] = add(s, abs(dw));
    } else {
      l[i] = s;
      la[i] = s;
    }
  }
  // 2x2 minors on (x, y): m[i][j] = x_i y_j - x_j y_i.
  double m[4][4];
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) m[i][j] = sub(mul(x[i], y[j]), mul(x[j], y[i]));
  // 3x3 minors M(ijk) = z_i m_jk - z_j m_ik + z_k m_ij (i < j < k).
  auto minor3 = [&](int i, int j, int k) { return add(sub(mul(z[i], m[j][k]), mul(z[j], m[i][k])), mul(z[k], m[i][j])); };
  const double m0 = minor3(1, 2, 3), m1 = minor3(0, 2, 3), m2 = minor3(0, 1, 3), m3 = minor3(0, 1, 2);
  const double det = add(sub(mul(l[0], m0), mul(l[1], m1)), sub(mul(l[2], m2), mul(l[3], m3)));
  constexpr double threshold = Weighted ? bounds::kPowerThreshold : bounds::kInsphereThreshold;
  constexpr int roundings = Weighted ? bounds::kPowerRoundings : bounds::kInsphereRoundings;
  // First a cheap bound B^ >= P^: the permanent's expression tree below evaluated with
  // every leaf replaced by the largest leaf of its kind (filter_bounds.hpp, section 5).
  double X = 0, Y = 0, Z = 0, L = 0;
  for (int i = 0; i < 4; ++i) {
    X = ax[i] > X ? ax[i] : X;
    Y = ay[i] > Y ? ay[i] : Y;
    Z = az[i] > Z ? az[i] : Z;
    L = la[i] > L ? la[i] : L;
  }
  const double qb = add(mul(X, Y), mul(X, Y));
  const double tb = mul(Z, qb);
  const double pb = add(add(tb, tb), tb);
  const double ub = mul(L, pb);
  const int quick = filter_decide(det, add(add(ub, ub), add(ub, ub)), threshold, roundings);
  if (quick != kUncertain) return quick;
  if (out) {
    const double xy = X > Y ? X : Y;
    *out = {det, xy > Z ? xy : Z};
  }
  // Then the permanent P^ itself: the same tree on the absolute values.
  double q[4][4];
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) q[i][j] = add(mul(ax[i], ay[j]), mul(ax[j], ay[i]));
  auto perm3 = [&](int i, int j, int k) { return add(add(mul(az[i], q[j][k]), mul(az[j], q[i][k])), mul(az[k], q[i][j])); };
  const double p0 = perm3(1, 2, 3), p1 = perm3(0, 2, 3), p2 = perm3(0, 1, 3), p3 = perm3(0, 1, 2);
  const double perm = add(add(mul(la[0], p0), mul(la[1], p1)), add(mul(la[2], p2), mul(la[3], p3)));
  return filter_decide(det, perm, threshold, roundings);
}

}  // namespace detail

// insphere(a,b,c,d,e) > 0 iff e is strictly inside the circumsphere of positive abcd
// (N = 16, T = 2^-408).
GDEL_HD inline int insphere_filter(const double* a, const double* b, const double* c,
                                   const double* d, const double* e, FilterValue* out = nullptr) {
  const double* p[5] = {a, b, c, d, e};
  return detail::lifted_filter<false>(p, nullptr, out);
}

// power(a,b,c,d,e; w) > 0 iff lifted e lies strictly below the hyperplane through lifted
// a..d (positive abcd), h = |p|^2 - w (N = 17, T = 2^-408).
GDEL_HD inline int power_filter(const double* a, const double* b, const double* c,
                                const double* d, const double* e, double wa, double wb,
                                double wc, double wd, double we) {
  const double* p[5] = {a, b, c, d, e};
  const double w[5] = {wa, wb, wc, wd, we};
  return detail::lifted_filter<true>(p, w);
}

}  // namespace gdel::geom
