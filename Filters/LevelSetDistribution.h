// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The particles spread over MPI ranks (pvbatch, pvserver): the Communicator of
// LevelSetCommunicator.h on a vtkMultiProcessController, and the two steps that prepare a rank's
// samples before the method runs on them:
// 1. Balanced: when the partition the pipeline gave is poor (a rank holds far more than its
//    share, or the ranks' bounding boxes overlap, as in a file read in interleaved pieces or
//    held by rank 0 alone), the particles are redistributed by space (SpreadBySpace: an
//    orthogonal recursive bisection of a sample, SpatialPartition.h), keeping their
//    coordinates' precision, every point array and the global ids.
// 2. WithGhosts: every rank receives copies of the other ranks' samples within a halo of its
//    own. Each owned sample asks for a reach (a multiple of its neighbourhood radius, set by the
//    filter); a sample is sent where its own kernel support or position falls in another
//    rank's reach box. The neighbourhoods of owned samples are then exactly those of a serial
//    run; ghosts whose neighbourhood the box cuts are marked (Neighborhoods::Truncated).
#ifndef LevelSetDistribution_h
#define LevelSetDistribution_h

#include "LevelSetCommunicator.h"

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <cstdint>
#include <string>
#include <vector>

class vtkMultiProcessController;
class vtkPointSet;
class vtkPolyData;

namespace lsi
{

struct Neighborhoods;

class Distribution : public Communicator
{
public:
  /// A null controller, or one of a single process, is a serial run.
  explicit Distribution(vtkMultiProcessController* controller);

  void Sum(double* values, int count) const override;
  void Max(double* values, int count) const override;
  void GatherAll(std::vector<double>& values) const override;
  void RefreshGhosts(std::vector<double>& perSample) const override;
  void MaxToOwners(std::vector<double>& perSample) const override;
  using Communicator::Max;
  using Communicator::Sum;

  /// The lowest rank's non-empty message, on every rank ("" when every rank passed "").
  std::string FirstProblem(const std::string& local) const;

  /// Every rank's number, in rank order, on every rank.
  std::vector<double> AllNumbers(double local) const;

  /// The input, or its particles redistributed by space when the partition is poor (`report`
  /// says why). Field data (the readers' markers) come from the lowest rank with particles.
  /// Null on every rank, `report` saying why, when a rank's piece did not arrive whole.
  vtkSmartPointer<vtkPointSet> Balanced(vtkPointSet* input, std::string& report);

  /// Every rank's particles spread by space (SpatialPartition of a sample of them), one part
  /// per rank, with their point arrays, global ids and coordinates unchanged. Null on every
  /// rank when a piece did not arrive whole (not what its sender counted).
  vtkSmartPointer<vtkPointSet> SpreadBySpace(vtkPointSet* input);

  /// Every rank's particles on rank 0 (others: empty), for inputs too small to spread.
  vtkSmartPointer<vtkPointSet> GatheredOnFirst(vtkPointSet* input);

  /// The owned samples followed by ghost copies of other ranks' samples: those inside this
  /// rank's `reachBox` (xmin, xmax, ymin, ...: the bounds of the boxes x_i +- reach_i over
  /// owned samples, HaloReachBox), or whose `support` (per sample, may be empty) reaches into
  /// it. `values` (f per sample) is extended. Null on every rank, with `problem` said, when a
  /// rank received a malformed message.
  vtkSmartPointer<vtkPolyData> WithGhosts(vtkPointSet* owned, const double reachBox[6],
    const std::vector<double>& support, std::vector<double>& values, std::string& problem);

  /// After the neighbour search on WithGhosts' output: the owned samples and the ghosts'
  /// owners in storage order; marks the ghosts whose neighbourhood the reach box cuts.
  void Attach(const Neighborhoods& geometry);

  vtkIdType OwnedCount = 0; // samples before the ghosts (input order)
  vtkIdType GhostCount = 0;
  // Seconds in communication (the waiting for slower ranks included), this rank.
  mutable double CommunicationSeconds = 0.0;

private:
  // Every rank's counts of what it sends to each rank (rank r's row r), from this rank's
  // `sending` (ids per rank), on every rank; `partners`: the ranks this one sends to or
  // receives from.
  std::vector<double> CountsSent(
    const std::vector<std::vector<vtkIdType>>& sending, std::vector<char>& partners) const;

  // Calls exchange(other) for every other rank with which this rank trades, in an order in
  // which blocking sends cannot deadlock (the lower rank of each pair sends first).
  template <typename Exchange>
  void WithEachPartner(const std::vector<char>& partners, Exchange&& exchange) const;

  // Sends perSample at `from[r]` to each partner r, which combines what it receives into its
  // samples `to[this rank]` (the same count, in the same order).
  template <typename Combine>
  void Trade(std::vector<double>& perSample, const std::vector<std::vector<std::uint32_t>>& from,
    const std::vector<std::vector<std::uint32_t>>& to, int tag, Combine&& combine) const;

  vtkMultiProcessController* Controller = nullptr;
  double ReachBox[6] = { 0, 0, 0, 0, 0, 0 };
  // Per rank: the input ids of the owned samples sent to it; the input ids of its ghosts here.
  std::vector<std::vector<vtkIdType>> SentIds, ReceivedIds;
  // The same in storage order (after Attach).
  std::vector<std::vector<std::uint32_t>> SentSamples, ReceivedSamples;
  std::vector<char> Partners; // ranks with which ghosts are traded
};

} // namespace lsi

#endif
