// Input validation for the public entry points.
#pragma once

#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "gdel/errors.hpp"
#include "geometry/predicates.hpp"

namespace gdel::api {

// Checks the point array (3 finite doubles per point) and returns the exponent k
// such that 2^k * points lies in the predicates' exact range (0 when it already
// does). Scaling by a power of two is exact and preserves every predicate's sign,
// so the triangulation of the scaled points is the triangulation of the input.
// Throws InvalidInput naming the first offending row, or when the ratio of the
// largest to the smallest non-zero magnitude is too large for any such scaling.
inline int validate_points(std::span<const double> pts) {
  if (pts.size() % 3 != 0)
    throw InvalidInput("points: expected 3 coordinates per point, got " + std::to_string(pts.size()) +
                       " values (not a multiple of 3)");
  double lo = HUGE_VAL, hi = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double x = pts[i];
    if (!std::isfinite(x))
      throw InvalidInput("points: row " + std::to_string(i / 3) + " has a non-finite coordinate (" +
                         std::to_string(x) + ")");
    const double a = std::fabs(x);
    if (a != 0) {
      lo = std::min(lo, a);
      hi = std::max(hi, a);
    }
  }
  if (hi == 0) return 0;
  bool in = true;
  for (double v : {lo, hi}) in = in && geom::coordinate_in_range(v);
  if (in) return 0;
  // Move the largest magnitude just under the top of the range.
  int ehi = std::ilogb(hi), elo = std::ilogb(lo);
  int k = 199 - ehi;
  // (a non-zero magnitude that the scaling flushes to zero would pass coordinate_in_range)
  const double slo = std::ldexp(lo, k), shi = std::ldexp(hi, k);
  if (slo == 0 || !geom::coordinate_in_range(slo) || !geom::coordinate_in_range(shi))
    throw InvalidInput("points: coordinate magnitudes span 2^" + std::to_string(elo) + " .. 2^" +
                       std::to_string(ehi) +
                       ", too wide to be handled exactly (the ratio of the largest to the smallest non-zero "
                       "|coordinate| must be at most 2^352)");
  return k;
}

// Weights (squared lengths) scaled with the coordinates' factor 2^k, i.e. by 2^(2k), and
// checked: finite, in the exact range, and not flushed to zero by the scaling. Throws
// InvalidInput naming the first offending row. `what` prefixes the message.
inline std::vector<double> scaled_weights(std::span<const double> w, int k, const std::string& what) {
  std::vector<double> s(w.begin(), w.end());
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!std::isfinite(w[i]))
      throw InvalidInput(what + ": row " + std::to_string(i) + " is not finite (" + std::to_string(w[i]) + ")");
    s[i] = std::ldexp(w[i], 2 * k);
    if ((w[i] != 0 && s[i] == 0) || !geom::weight_in_range(s[i]))
      throw InvalidInput(what + ": row " + std::to_string(i) + " (" + std::to_string(w[i]) +
                         ") is outside the exact range (|w| in 2^-356 .. 2^400, or 0, after the coordinates' scaling "
                         "by 2^" + std::to_string(k) + ")");
  }
  return s;
}

inline std::vector<double> scaled(std::span<const double> pts, int k) {
  std::vector<double> s(pts.begin(), pts.end());
  for (double& x : s) x = std::ldexp(x, k);
  return s;
}

}  // namespace gdel::api
