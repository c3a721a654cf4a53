#pragma once
// Point sets in the unit square [0, 1)^2 for probe-point sampling: the
// classical low-discrepancy constructions and their random counterparts.
//
// Why several: a probe plan wants points spread evenly (every part of a
// region looked at, no clusters that waste CMM time) but not on a lattice
// that can alias with a periodic machining error (scallops, feed marks).
// Low-discrepancy sets (Hammersley, Halton) and stratified (jittered) sets
// are both: their star discrepancy falls like (log N)^2 / N against 1/sqrt(N)
// for independent random points, which is why they reconstruct a surface
// with a smaller error for the same number of touches (Lee, Mou & Shin 1997;
// tests/planning/test_sampling_accuracy.cpp shows the numbers).
//
// Every set is seeded and reproducible. The deterministic constructions are
// randomised by a Cranley-Patterson rotation: one uniform shift (from the
// seed) added to every point modulo 1. That keeps the discrepancy of the set
// (on the torus) and makes each plan an unbiased sample, so repeated seeds
// give independent plans whose spread can be compared with random ones.
//
// Sequences (Halton, random) can be extended one point at a time: the first
// n points of a longer sequence are the n-point sequence, so plans at higher
// density contain the lower-density ones. Sets (Hammersley, stratified,
// grid) are built for a given N; a different N gives a different set.
#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <vector>

namespace furrow {

// Van der Corput radical inverse of `index` in `base` (>= 2): the digits of
// index mirrored about the radix point, in [0, 1).
double radical_inverse(std::uint64_t index, unsigned base);

// Uniform shift in [0, 1)^2 drawn from `seed` (Cranley-Patterson rotation).
Eigen::Vector2d rotation_from_seed(std::uint64_t seed);

// Adds `shift` to `p` modulo 1 in each coordinate.
Eigen::Vector2d rotate(const Eigen::Vector2d& p, const Eigen::Vector2d& shift);

// Halton sequence in bases 2 and 3, point `index` (index 0 is (0, 0) before
// the rotation).
Eigen::Vector2d halton_point(std::uint64_t index);

// Hammersley set of n points: ((i + 1/2) / n, radical_inverse(i, 2)).
std::vector<Eigen::Vector2d> hammersley_set(std::size_t n);

// Strata counts for about n cells whose shape on the surface is square when
// the unit square stands for a patch `aspect` = width / height: nx * ny >= n,
// nx / ny close to aspect. Both >= 1.
Eigen::Vector2i strata_for(std::size_t n, double aspect);

// One point per cell of an nx x ny grid: the cell centre (grid) or a uniform
// random point in the cell (stratified, jittered), row by row.
std::vector<Eigen::Vector2d> grid_set(const Eigen::Vector2i& strata);
std::vector<Eigen::Vector2d> stratified_set(const Eigen::Vector2i& strata, std::mt19937_64& rng);

// Independent uniform point.
Eigen::Vector2d random_point(std::mt19937_64& rng);

}  // namespace furrow
