// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The MLS stencils computed ahead by a helper thread (Neighborhoods::PrecomputeStencils, run
// while the flood's serial distance propagation runs) against those computed when asked for
// (EnsureStencils), on random particles with a thin slab and a flat patch beside them:
//   - the same stencils, to the bit (the gradients they give);
//   - the same counts of computed, singular and thin stencils, whichever computed them: the
//     ones computed ahead but never asked for are not counted;
//   - a helper told to stop before it starts computes nothing.
#include "LevelSetNeighborhoods.h"
#include "TestCheck.h"

#include "vtkNew.h"
#include "vtkPoints.h"

#include <atomic>
#include <iostream>
#include <random>
#include <thread>
#include <vector>

namespace
{
using lsi::test::Check;

vtkNew<vtkPoints> MakePoints()
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int i = 0; i < 3000; ++i) // a unit box
  {
    points->InsertNextPoint(unit(random), unit(random), unit(random));
  }
  for (int i = 0; i < 400; ++i) // a slab 1e-5 thick: thin neighbourhoods
  {
    points->InsertNextPoint(2.0 + unit(random), unit(random), 0.5 + 1e-5 * unit(random));
  }
  for (int i = 0; i < 300; ++i) // an exactly flat patch: singular fits
  {
    points->InsertNextPoint(4.0 + unit(random), unit(random), 0.5);
  }
  return points;
}

struct Counts
{
  std::size_t Computed, Singular, Thin;
  bool operator==(const Counts& o) const
  {
    return Computed == o.Computed && Singular == o.Singular && Thin == o.Thin;
  }
};

Counts CountsOf(const lsi::Neighborhoods& g)
{
  return { g.ComputedStencils, g.SingularSamples, g.ThinSamples };
}

// The gradient of a linear field by each listed sample's stencil.
std::vector<double> Gradients(const lsi::Neighborhoods& g, const std::vector<std::size_t>& list)
{
  std::vector<double> out;
  for (std::size_t i : list)
  {
    const std::uint32_t* ids = g.NeighborsOf(i);
    const Eigen::Vector3d gradient = g.GradientAt(i, [&](std::size_t m) {
      const double* x = g.Position(ids[m]);
      return x[0] + 2.0 * x[1] - x[2];
    });
    out.insert(out.end(), gradient.data(), gradient.data() + 3);
  }
  return out;
}
} // namespace

int main()
{
  vtkNew<vtkPoints> points = MakePoints();
  lsi::Neighborhoods asked, ahead, stopped;
  for (lsi::Neighborhoods* g : { &asked, &ahead, &stopped })
  {
    lsi::BuildNeighborhoods(points, 24, *g, lsi::AbortCheck());
  }
  const std::size_t n = asked.NumberOfSamples;
  // Every other sample is asked for; the helper computes those and the others before them.
  std::vector<std::size_t> list;
  for (std::size_t i = 0; i < n; i += 2)
  {
    list.push_back(i);
  }
  std::vector<std::uint32_t> aheadList;
  for (std::size_t i = 0; i < n; ++i)
  {
    aheadList.push_back(static_cast<std::uint32_t>(i));
  }

  asked.EnsureStencils(list);
  const Counts reference = CountsOf(asked);
  Check(reference.Computed == list.size(), "every listed stencil counted once");
  Check(reference.Singular > 0 && reference.Thin > 0,
    "the flat patch gives singular stencils and the slab thin ones (the counts are tested)");

  std::atomic<bool> stop(false);
  std::thread helper([&]() { ahead.PrecomputeStencils(aheadList.data(), aheadList.size(), stop); });
  helper.join();
  Check(CountsOf(ahead) == Counts{ 0, 0, 0 }, "stencils computed ahead are not counted yet");
  ahead.EnsureStencils(list);
  Check(CountsOf(ahead) == reference,
    "the counts after computing ahead are those of computing when asked");
  Check(Gradients(ahead, list) == Gradients(asked, list),
    "the stencils computed ahead give the same gradients, to the bit");
  ahead.EnsureStencils(list); // asked again: nothing new
  Check(CountsOf(ahead) == reference, "a stencil asked for twice is counted once");

  stop = true;
  std::thread idle([&]() { stopped.PrecomputeStencils(aheadList.data(), aheadList.size(), stop); });
  idle.join();
  Check(stopped.StencilState == std::vector<unsigned char>(n, 0),
    "a helper told to stop computes nothing");

  std::cout << (lsi::test::Failures() ? "stencil cache tests FAILED\n"
                                      : "stencil cache tests passed\n");
  return lsi::test::Failures() ? 1 : 0;
}
