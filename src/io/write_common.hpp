// Argument checks shared by the writers (write.cpp, write_mesh.cpp). Each throws
// gdel::InvalidInput "cannot write '<path>': <what>".
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

#include "mesh/conventions.hpp"

namespace gdel::io::detail {

[[noreturn]] void bad_argument(const std::filesystem::path& path, const std::string& what);

// Number of points; checks that xyz holds triples and weights is empty or one per point.
std::size_t check_points(const std::filesystem::path& path, std::span<const double> xyz,
                         std::span<const double> weights);

// Point i (and its weight) finite.
void check_finite(const std::filesystem::path& path, std::span<const double> xyz, std::span<const double> weights,
                  std::size_t i);

void check_tet_vertex(const std::filesystem::path& path, std::size_t t, vid_t v, std::size_t num_points);
void check_neighbour(const std::filesystem::path& path, std::size_t t, tid_t v, std::size_t m);
void check_tets(const std::filesystem::path& path, std::span<const vid_t> tets);
void check_neighbours(const std::filesystem::path& path, std::span<const tid_t> neighbours);

// Everything a mesh writer needs, before any file is touched: shapes, finite points and
// weights, vertex ids in 0..n-1, neighbours -1 or a tet id, one neighbour row per tet (when
// neighbours are given). Messages name points_path / tets_path / neighbours_path (the same
// path for single-file formats). Returns the number of points.
std::size_t check_mesh(const std::filesystem::path& points_path, const std::filesystem::path& tets_path,
                       const std::filesystem::path& neighbours_path, std::span<const double> xyz,
                       std::span<const vid_t> tets, std::span<const tid_t> neighbours,
                       std::span<const double> weights);

}  // namespace gdel::io::detail
