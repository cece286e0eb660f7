// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// What the first write to fresh memory costs on this machine, the measurement behind
// Filters/Numerics/UninitializedVector.h: seconds to make a per-sample array of 2M doubles
// (16 MB) in fresh pages,
//   - resize:            std::vector's resize() (zeroes on one thread, faulting page by page);
//   - touch, 2 threads:  uninitialised storage, each half zeroed by a thread of its own;
//   - mapped, resize:    the pages mapped in one call (MapPagesNow), then resize();
//   - mapped, 2 threads: each half mapped by a thread of its own, then resize();
//   - huge pages:        2 MB pages asked for (AdviseHugePages), then resize(): a fault per 2 MB
//                        where the kernel grants them (transparent huge pages, madvise mode);
//   - ResizeMapped:      both (what the filter's per-sample arrays do);
//   - resident:          the same writes again into the first array, whose pages are mapped.
// Every array is kept until the end, so each one gets fresh pages. Median of REPEATS (default 9).
// Reports numbers and asserts nothing.
//   LevelSetPageFaults [REPEATS]
#include "UninitializedVector.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <thread>
#include <vector>

namespace
{
constexpr std::size_t Count = 2000000; // doubles: 16 MB

double Seconds(const std::function<void()>& work)
{
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// Runs part(0) on a new thread and part(1) on this one.
void OnTwoThreads(const std::function<void(int)>& part)
{
  std::thread other(part, 0);
  part(1);
  other.join();
}
} // namespace

int main(int argc, char* argv[])
{
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 9;
  std::vector<std::vector<double>> kept;
  std::vector<lsi::UninitializedVector<double>> keptUninitialized;
  std::vector<double> resize, touch, mapped, mappedTwo, huge, both, resident;
  const std::size_t half = Count / 2;
  for (int r = 0; r < repeats; ++r)
  {
    resize.push_back(Seconds([&]() {
      kept.emplace_back();
      kept.back().resize(Count);
    }));
    touch.push_back(Seconds([&]() {
      keptUninitialized.emplace_back(Count);
      double* values = keptUninitialized.back().data();
      OnTwoThreads([&](int k) { std::fill(values + k * half, values + (k + 1) * half, 0.0); });
    }));
    mapped.push_back(Seconds([&]() {
      kept.emplace_back();
      kept.back().reserve(Count);
      lsi::MapPagesNow(kept.back().data(), Count * sizeof(double));
      kept.back().resize(Count);
    }));
    huge.push_back(Seconds([&]() {
      kept.emplace_back();
      kept.back().reserve(Count);
      lsi::AdviseHugePages(kept.back());
      kept.back().resize(Count);
    }));
    both.push_back(Seconds([&]() {
      kept.emplace_back();
      lsi::ResizeMapped(kept.back(), Count);
    }));
    mappedTwo.push_back(Seconds([&]() {
      kept.emplace_back();
      std::vector<double>& values = kept.back();
      values.reserve(Count);
      OnTwoThreads(
        [&](int k) { lsi::MapPagesNow(values.data() + k * half, half * sizeof(double)); });
      values.resize(Count);
    }));
    resident.push_back(Seconds([&]() { kept.front().assign(Count, static_cast<double>(r)); }));
  }
  std::printf("fresh 16 MB array (2M doubles), median of %d, seconds\n", repeats);
  std::printf("%-20s %.4f\n", "resize", Median(resize));
  std::printf("%-20s %.4f\n", "touch, 2 threads", Median(touch));
  std::printf("%-20s %.4f\n", "mapped, resize", Median(mapped));
  std::printf("%-20s %.4f\n", "mapped, 2 threads", Median(mappedTwo));
  std::printf("%-20s %.4f\n", "huge pages", Median(huge));
  std::printf("%-20s %.4f\n", "ResizeMapped", Median(both));
  std::printf("%-20s %.4f\n", "resident", Median(resident));
  return EXIT_SUCCESS;
}
