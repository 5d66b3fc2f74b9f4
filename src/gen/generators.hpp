// Deterministic point generators for tests and benchmarks (host only).
//
// Every generator returns points as an array of xyz triples (AoS: x0,y0,z0,x1,...)
// and guarantees:
//  * determinism: the output depends only on (n, seed) and is bit-identical on every
//    platform. Randomness comes from std::mt19937_64 (whose output sequence the C++
//    standard fixes) through our own conversions; no std::*_distribution (their output
//    is implementation-defined) and no libm transcendental function (not correctly
//    rounded, so they differ between libraries) is used. Only +, -, *, / and sqrt
//    (all correctly rounded in IEEE 754) enter the coordinates, and the project builds
//    host code with -ffp-contract=off, so no fused multiply-add changes a result.
//  * distinctness: the n points are pairwise distinct (checked exactly; generation goes
//    on until n distinct points exist).
//  * n at most 2^31 - 1 (vertex ids are int32), otherwise InvalidInput.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace gdel::gen {

enum class Distribution {
  Uniform,    // "uniform":    uniform in the unit cube [0,1)^3
  Gaussian,   // "gaussian":   each coordinate normal with mean 0.5, sigma 0.1 (unclipped)
  Ball,       // "ball":       uniform in the ball of radius 0.45 centred at (0.5,0.5,0.5)
  ThinShell,  // "thin_shell": between the spheres of radius 0.45 and 0.451 centred at 0.5
  Grid,       // "grid":       distinct points of the integer grid {0..511}^3
  Sphere,     // "sphere":     integer points exactly on the sphere x^2+y^2+z^2 = d^2
  SkewLines,  // "skew_lines": n/2 points on each of two skew lines; Theta(n^2) Delaunay tets
};

// Every distribution, in the order of the enum.
inline constexpr std::array<Distribution, 7> kAllDistributions = {
    Distribution::Uniform, Distribution::Gaussian,  Distribution::Ball,     Distribution::ThinShell,
    Distribution::Grid,    Distribution::Sphere,    Distribution::SkewLines};

// The name used on command lines and in file names ("uniform", "thin_shell", ...).
std::string_view to_string(Distribution d) noexcept;
// Inverse of to_string (case-insensitive). Throws gdel::InvalidInput naming the valid names.
Distribution parse_distribution(std::string_view name);

// Parameters of the distributions (documented constants, used by the tests).
inline constexpr double kGaussianMean = 0.5;
inline constexpr double kGaussianSigma = 0.1;
inline constexpr double kBallCentre = 0.5;
inline constexpr double kBallRadius = 0.45;
inline constexpr double kShellInner = 0.45;
inline constexpr double kShellOuter = 0.451;
inline constexpr std::uint32_t kGridSide = 512;             // grid coordinates 0..511
inline constexpr std::uint64_t kSphereMaxRadius = 1u << 26;  // d^2 < 2^53: exact in double

// The one entry point: n distinct points of distribution d.
std::vector<double> generate(Distribution d, std::size_t n, std::uint64_t seed);

// Uniform in [0,1)^3; coordinates are multiples of 2^-53.
std::vector<double> uniform(std::size_t n, std::uint64_t seed);

// Normal per coordinate, mean kGaussianMean, standard deviation kGaussianSigma, drawn by
// Marsaglia's polar method with a deterministic logarithm (see generators.cpp). Points are
// not clipped to the unit cube (about 1 in 1.7 million coordinates lies outside [0,1]).
std::vector<double> gaussian(std::size_t n, std::uint64_t seed);

// Uniform in the open ball of radius kBallRadius centred at (kBallCentre)^3 (rejection
// sampling from the cube).
std::vector<double> ball(std::size_t n, std::uint64_t seed);

// Direction uniform on the sphere, radius uniform in [kShellInner, kShellOuter] (up to the
// rounding of one multiplication and one addition), centred at (0.5,0.5,0.5). The radius is
// uniform rather than volume-weighted: in a shell this thin the two differ by < 0.5%.
std::vector<double> thin_shell(std::size_t n, std::uint64_t seed);

// n distinct points of the grid {0..kGridSide-1}^3 in random order, each coordinate an
// integer times `scale`. scale = 1 gives integer-valued doubles; a power of two (e.g.
// 1.0/512 for points in [0,1)^3) keeps every coordinate exact. n <= 512^3, otherwise
// InvalidInput.
std::vector<double> grid(std::size_t n, std::uint64_t seed, double scale = 1.0);

// n distinct integer points exactly on the sphere of radius d = sphere_radius(n) centred at
// the origin: x^2 + y^2 + z^2 = d^2 holds exactly (|coordinates| <= d < 2^26, so the
// coordinates, their squares and the sum of squares are all exact doubles). The points are
// x = m^2+n^2-p^2-q^2, y = 2(mq+np), z = 2(nq-mp) over all integer quadruples with
// m^2+n^2+p^2+q^2 = d (the rotation of (d,0,0) by the quaternion m+ni+pj+qk), d odd;
// a seeded random subset of n of the distinct ones is returned.
std::vector<double> sphere(std::size_t n, std::uint64_t seed);

// The radius used by sphere(n): the smallest odd d whose construction above yields at least
// n distinct points. Throws InvalidInput when that would need d > kSphereMaxRadius.
std::uint64_t sphere_radius(std::size_t n);

// Number of distinct points the sphere construction yields for odd d (d >= 1).
std::size_t sphere_point_count(std::uint64_t d);

namespace detail {
// Closed form of sphere_point_count(d) for odd d: 2 * prod over prime powers p^a || d of
// p^a (p = 1 mod 4) or sigma(p^a) = 1 + p + ... + p^a (p = 3 mod 4). Observed, not proven
// here: the tests compare it with the enumeration; sphere() uses it only to skip radii.
std::uint64_t sphere_point_count_formula(std::uint64_t d);
}  // namespace detail

// ceil(n/2) points (t,0,0) followed by floor(n/2) points (0,t,1), each t a distinct multiple
// of 2^-32 in [0,1) (exact in double), in random order within each line. The Delaunay
// triangulation of such a set has (ceil(n/2)-1)(floor(n/2)-1) tetrahedra.
std::vector<double> skew_lines(std::size_t n, std::uint64_t seed);

// n weights uniform in [0, max) for regular-triangulation tests (multiples of max*2^-53,
// never equal to max). max must be finite and > 0, otherwise InvalidInput.
std::vector<double> weights(std::size_t n, std::uint64_t seed, double max);

}  // namespace gdel::gen
