// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Under MPI, how far a rank's halo reaches (Distribution::WithGhosts): the bounds of the boxes
// x_i +- (factor * h_i + band) over the rank's samples, h_i each one's neighbourhood radius. It
// is computed exactly without computing every sample's neighbour list: most samples lie too far
// inside to move a bound, and an upper bound on h_i says which, without a search.
#ifndef LevelSetHaloReach_h
#define LevelSetHaloReach_h

#include "LevelSetNeighborhoods.h"
#include "LevelSetParallel.h"

#include <cstddef>
#include <vector>

namespace lsi
{

/// An upper bound on each sample's radius h_i (the distance to its Stride - 1 nearest other
/// samples' farthest) from samples next to it in storage order: any Stride - 1 other samples
/// lie no nearer than its nearest ones, so the farthest of them bounds h_i. The smallest over
/// the windows before, around and after the sample. Empty when there are too few samples.
std::vector<double> RadiusBounds(const Neighborhoods& geometry);

/// The same bound for sample i alone (+inf when there are too few samples).
double RadiusBound(const Neighborhoods& geometry, std::size_t i);

/// A tighter bound, and a costlier one (a partial sort of a few hundred distances): the
/// (Stride - 1)-th nearest of the samples within `half` places of sample i in storage order, i
/// excluded (+inf when fewer than Stride - 1 lie there). Any Stride - 1 of them lie no nearer
/// than i's nearest ones, so their farthest bounds h_i; the nearest of many is near h_i.
/// `squared`: scratch space.
double WindowRadiusBound(
  const Neighborhoods& geometry, std::size_t i, std::size_t half, std::vector<double>& squared);

/// HaloReachBox's samples per side whose exact reach is taken first.
constexpr std::size_t HaloFirstPerSide = 64;

/// The halo's box (xmin, xmax, ymin, ...) over the samples: min and max of x_i -+ (factor * h_i
/// + band), each h_i as RadiusOf gives it. Lists are computed (in parallel) only for the samples
/// whose bounded reach could pass the reach of the samples that bound the box so far: by
/// RadiusBound, then, for those that pass it, by WindowRadiusBound.
/// `computed` receives how many samples needed their lists. False only when aborted; an empty
/// set gives the empty box (+inf, -inf, ...). `firstPerSide`: how many samples per side, those
/// with the farthest bounded reach, set the reach to pass (any number gives the same box).
/// `wanted` (null: all): the sides (-x, +x, -y, ...) to compute; the others are unbounded
/// (-inf or +inf) at no cost: under MPI, the sides beyond which no other rank holds a sample.
bool HaloReachBox(const Neighborhoods& geometry, double factor, double band, double box[6],
  std::size_t& computed, const AbortCheck& aborted, std::size_t firstPerSide = HaloFirstPerSide,
  const bool wanted[6] = nullptr);

} // namespace lsi

#endif
