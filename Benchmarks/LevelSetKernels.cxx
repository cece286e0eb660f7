// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The per-sample MLS kernels that most of a run's time goes through, each timed alone on one
// thread over fixed random neighbourhoods (microseconds per call, the fastest of 5 rounds):
//   - the quadratic-or-linear fit of the data refinement and of a slide (54 samples);
//   - the linear fit (54 samples);
//   - the linear fit's value weights, for interpolating arrays onto the surface (54 samples);
//   - a gradient stencil, for the evolution (27 samples).
// Reports numbers and asserts nothing; the checksums show that two builds compute the same.
//   LevelSetKernels [CALLS]
#include "MovingLeastSquares.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace
{
constexpr int Neighbourhoods = 64;

// Random positions in a cube of side 2 around the origin and values of a quadratic with noise.
struct Samples
{
  std::vector<double> Positions, Values;
  Samples(int perNeighbourhood, unsigned seed)
  {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Positions.resize(3 * perNeighbourhood * Neighbourhoods);
    for (double& x : Positions)
    {
      x = unit(random);
    }
    for (std::size_t i = 0; i < Positions.size() / 3; ++i)
    {
      const double* x = &Positions[3 * i];
      Values.push_back(x[0] * x[0] + 0.3 * x[1] + 0.1 * x[1] * x[2] + 0.01 * unit(random));
    }
  }
};

// The fastest of 5 rounds of `calls` calls, in microseconds per call.
template <typename Call>
double MicrosecondsPerCall(int calls, Call&& call)
{
  double fastest = HUGE_VAL;
  for (int round = 0; round < 5; ++round)
  {
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < calls; ++k)
    {
      call(k);
    }
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fastest = std::min(fastest, 1e6 * seconds / calls);
  }
  return fastest;
}
} // namespace

int main(int argc, char* argv[])
{
  const int calls = argc > 1 ? std::max(1, std::atoi(argv[1])) : 200000;
  const int wide = 54, narrow = 27;
  const Samples fit(wide, 1), stencil(narrow, 2);
  // The centre moves a little from call to call, as along a slide.
  auto centreOf = [](int k, double c[3]) {
    c[0] = 0.01 * (k % 7);
    c[1] = 0.0;
    c[2] = 0.0;
  };
  double checksum[4] = { 0.0, 0.0, 0.0, 0.0 };
  const double quadratic = MicrosecondsPerCall(calls, [&](int k) {
    const int s = k % Neighbourhoods;
    double c[3], value;
    centreOf(k, c);
    Eigen::Vector3d gradient;
    Eigen::Matrix3d hessian;
    bool isQuadratic = false;
    lsi::FitLinearOrQuadratic(
      c, wide, [&](std::size_t j) { return &fit.Positions[3 * (wide * s + j)]; },
      [&](std::size_t j) { return fit.Values[wide * s + j]; }, 1.8, 3.5, value, gradient,
      isQuadratic, &hessian);
    checksum[0] += value + gradient[0] + hessian(0, 0);
  });
  const double linear = MicrosecondsPerCall(calls, [&](int k) {
    const int s = k % Neighbourhoods;
    double c[3], value;
    centreOf(k, c);
    Eigen::Vector3d gradient;
    lsi::FitLinear(
      c, wide, [&](std::size_t j) { return &fit.Positions[3 * (wide * s + j)]; },
      [&](std::size_t j) { return fit.Values[wide * s + j]; }, 1.8, value, gradient);
    checksum[1] += value + gradient[1];
  });
  std::vector<double> weights(wide);
  const double valueWeights = MicrosecondsPerCall(calls, [&](int k) {
    const int s = k % Neighbourhoods;
    double c[3];
    centreOf(k, c);
    lsi::LinearValueWeights(
      c, wide, [&](std::size_t j) { return &fit.Positions[3 * (wide * s + j)]; }, 1.8,
      weights.data());
    checksum[2] += weights[3];
  });
  std::vector<double> gradients(3 * narrow);
  const double gradientStencil = MicrosecondsPerCall(calls, [&](int k) {
    const int s = k % Neighbourhoods;
    double c[3];
    centreOf(k, c);
    lsi::BuildLinearStencil(
      c, narrow, [&](std::size_t j) { return &stencil.Positions[3 * (narrow * s + j)]; }, 1.8,
      lsi::LinearStencilView{ gradients.data(), nullptr });
    checksum[3] += gradients[4];
  });
  std::printf("%-44s %8s  %s\n", "kernel (one thread)", "us/call", "checksum");
  std::printf(
    "%-44s %8.3f  %.17g\n", "quadratic-or-linear fit, 54 samples", quadratic, checksum[0]);
  std::printf("%-44s %8.3f  %.17g\n", "linear fit, 54 samples", linear, checksum[1]);
  std::printf(
    "%-44s %8.3f  %.17g\n", "interpolation value weights, 54 samples", valueWeights, checksum[2]);
  std::printf("%-44s %8.3f  %.17g\n", "gradient stencil, 27 samples", gradientStencil, checksum[3]);
  return EXIT_SUCCESS;
}
