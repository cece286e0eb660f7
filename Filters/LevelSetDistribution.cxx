// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetDistribution.h"

#include "LevelSetGhostMessages.h"
#include "LevelSetHaloReach.h"
#include "LevelSetNeighborhoods.h"
#include "LevelSetParallel.h"
#include "SpatialPartition.h"

#include "vtkCommunicator.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace lsi
{

namespace
{
enum Tag
{
  GhostTag = 71001,
  RefreshTag = 71002,
  ToOwnersTag = 71003,
  GatherTag = 71004,
  SpreadTag = 71005
};

// The points and point arrays of `ids` of `input` (all of them when ids is null), as a vertex-
// free vtkPolyData, the form in which pieces travel between ranks.
vtkSmartPointer<vtkPolyData> PointsOf(vtkPointSet* input, const std::vector<vtkIdType>* ids)
{
  auto piece = vtkSmartPointer<vtkPolyData>::New();
  const vtkIdType n =
    ids ? static_cast<vtkIdType>(ids->size()) : (input ? input->GetNumberOfPoints() : 0);
  vtkNew<vtkIdList> list;
  list->SetNumberOfIds(n);
  for (vtkIdType k = 0; k < n; ++k)
  {
    list->SetId(k, ids ? (*ids)[k] : k);
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (vtkIdType k = 0; k < n; ++k)
  {
    points->SetPoint(k, input->GetPoint(list->GetId(k)));
  }
  piece->SetPoints(points);
  if (!input)
  {
    return piece;
  }
  vtkPointData* from = input->GetPointData();
  for (int a = 0; a < from->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = from->GetAbstractArray(a);
    // (An array shorter than the points is malformed: it cannot travel, and is left out.)
    if (!array || !array->GetName() || array->GetNumberOfTuples() < input->GetNumberOfPoints())
    {
      continue;
    }
    vtkSmartPointer<vtkAbstractArray> subset = vtk::TakeSmartPointer(array->NewInstance());
    subset->SetName(array->GetName());
    subset->SetNumberOfComponents(array->GetNumberOfComponents());
    subset->SetNumberOfTuples(n);
    array->GetTuples(list, subset);
    if (array == from->GetGlobalIds())
    {
      piece->GetPointData()->SetGlobalIds(vtkDataArray::SafeDownCast(subset));
    }
    else
    {
      piece->GetPointData()->AddArray(subset);
    }
  }
  piece->GetFieldData()->ShallowCopy(input->GetFieldData());
  return piece;
}

// `pieces` one after the other: the first piece's arrays, each filled from the later pieces'
// array of the same name (zeros where a piece lacks it).
vtkSmartPointer<vtkPolyData> Concatenated(const std::vector<vtkSmartPointer<vtkPolyData>>& pieces)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  vtkIdType total = 0;
  for (const auto& piece : pieces)
  {
    total += piece->GetNumberOfPoints();
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(total);
  vtkIdType at = 0;
  for (const auto& piece : pieces)
  {
    for (vtkIdType k = 0; k < piece->GetNumberOfPoints(); ++k)
    {
      points->SetPoint(at++, piece->GetPoint(k));
    }
  }
  out->SetPoints(points);
  vtkPointData* first = pieces.front()->GetPointData();
  for (int a = 0; a < first->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* model = first->GetAbstractArray(a);
    vtkSmartPointer<vtkAbstractArray> joined = vtk::TakeSmartPointer(model->NewInstance());
    joined->SetName(model->GetName());
    joined->SetNumberOfComponents(model->GetNumberOfComponents());
    joined->SetNumberOfTuples(total);
    if (auto* numbers = vtkDataArray::SafeDownCast(joined))
    {
      numbers->Fill(0.0);
    }
    at = 0;
    for (const auto& piece : pieces)
    {
      vtkAbstractArray* part = piece->GetPointData()->GetAbstractArray(model->GetName());
      const vtkIdType n = piece->GetNumberOfPoints();
      if (part && part->GetNumberOfComponents() == model->GetNumberOfComponents() && n > 0 &&
        part->GetNumberOfTuples() >= n)
      {
        joined->InsertTuples(at, n, 0, part);
      }
      at += n;
    }
    if (model == first->GetGlobalIds())
    {
      out->GetPointData()->SetGlobalIds(vtkDataArray::SafeDownCast(joined));
    }
    else
    {
      out->GetPointData()->AddArray(joined);
    }
  }
  out->GetFieldData()->ShallowCopy(pieces.front()->GetFieldData());
  return out;
}

// Adds the time of a scope (communication, and the waiting for other ranks in it) to a total;
// nested scopes count once.
class CommunicationTimer
{
public:
  explicit CommunicationTimer(double& total)
    : Total(total)
    , Outer(Depth++ == 0)
    , Start(std::chrono::steady_clock::now())
  {
  }
  ~CommunicationTimer()
  {
    --Depth;
    if (this->Outer)
    {
      this->Total +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - this->Start).count();
    }
  }

private:
  static thread_local int Depth;
  double& Total;
  bool Outer;
  std::chrono::steady_clock::time_point Start;
};
thread_local int CommunicationTimer::Depth = 0;

double BoxDistance(const double* x, const double* box)
{
  double d2 = 0.0;
  for (int d = 0; d < 3; ++d)
  {
    const double below = box[2 * d] - x[d], above = x[d] - box[2 * d + 1];
    const double gap = std::max(0.0, std::max(below, above));
    d2 += gap * gap;
  }
  return std::sqrt(d2);
}
} // namespace

Distribution::Distribution(vtkMultiProcessController* controller)
  : Controller(controller)
{
  if (controller)
  {
    this->Rank = controller->GetLocalProcessId();
    this->Size = controller->GetNumberOfProcesses();
  }
}

void Distribution::Sum(double* values, int count) const
{
  const CommunicationTimer timer(this->CommunicationSeconds);
  if (this->Size > 1)
  {
    std::vector<double> in(values, values + count);
    this->Controller->AllReduce(in.data(), values, count, vtkCommunicator::SUM_OP);
  }
}

void Distribution::Max(double* values, int count) const
{
  const CommunicationTimer timer(this->CommunicationSeconds);
  if (this->Size > 1)
  {
    std::vector<double> in(values, values + count);
    this->Controller->AllReduce(in.data(), values, count, vtkCommunicator::MAX_OP);
  }
}

std::vector<double> Distribution::AllNumbers(double local) const
{
  const CommunicationTimer timer(this->CommunicationSeconds);
  std::vector<double> all(static_cast<std::size_t>(this->Size), local);
  if (this->Size > 1)
  {
    this->Controller->AllGather(&local, all.data(), 1);
  }
  return all;
}

void Distribution::GatherAll(std::vector<double>& values) const
{
  const CommunicationTimer timer(this->CommunicationSeconds);
  if (this->Size <= 1)
  {
    return;
  }
  std::vector<double> counts = this->AllNumbers(static_cast<double>(values.size()));
  std::vector<vtkIdType> lengths(counts.size()), offsets(counts.size());
  vtkIdType total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r)
  {
    lengths[r] = static_cast<vtkIdType>(counts[r]);
    offsets[r] = total;
    total += lengths[r];
  }
  std::vector<double> all(static_cast<std::size_t>(total) + 1);
  std::vector<double> mine(values);
  mine.push_back(0.0); // never a null buffer
  this->Controller->AllGatherV(
    mine.data(), all.data(), static_cast<vtkIdType>(values.size()), lengths.data(), offsets.data());
  all.resize(static_cast<std::size_t>(total));
  values.swap(all);
}

std::string Distribution::FirstProblem(const std::string& local) const
{
  if (this->Size <= 1)
  {
    return local;
  }
  const std::vector<double> lengths = this->AllNumbers(static_cast<double>(local.size()));
  for (int r = 0; r < this->Size; ++r)
  {
    const auto length = static_cast<vtkIdType>(lengths[r]);
    if (length == 0)
    {
      continue;
    }
    std::string message(static_cast<std::size_t>(length), ' ');
    if (r == this->Rank)
    {
      message = local;
    }
    this->Controller->Broadcast(&message[0], length, r);
    return message;
  }
  return std::string();
}

std::vector<double> Distribution::CountsSent(
  const std::vector<std::vector<vtkIdType>>& sending, std::vector<char>& partners) const
{
  const std::size_t size = static_cast<std::size_t>(this->Size);
  std::vector<double> counts(size), all(size * size);
  for (std::size_t r = 0; r < size; ++r)
  {
    counts[r] = static_cast<double>(sending[r].size());
  }
  this->Controller->AllGather(counts.data(), all.data(), this->Size);
  partners.assign(size, 0);
  for (std::size_t r = 0; r < size; ++r)
  {
    partners[r] = (counts[r] > 0 || all[r * size + this->Rank] > 0) ? 1 : 0;
  }
  return all;
}

template <typename Exchange>
void Distribution::WithEachPartner(const std::vector<char>& partners, Exchange&& exchange) const
{
  for (int other = 0; other < this->Size; ++other)
  {
    if (other != this->Rank && partners[other])
    {
      exchange(other, this->Rank < other);
    }
  }
}

vtkSmartPointer<vtkPointSet> Distribution::Balanced(vtkPointSet* input, std::string& report)
{
  const CommunicationTimer timer(this->CommunicationSeconds);
  const vtkIdType n = input->GetNumberOfPoints();
  double bounds[6] = { 1, -1, 1, -1, 1, -1 };
  if (n > 0)
  {
    input->GetBounds(bounds);
  }
  const std::vector<double> counts = this->AllNumbers(static_cast<double>(n));
  std::vector<double> boxes(6 * static_cast<std::size_t>(this->Size));
  this->Controller->AllGather(bounds, boxes.data(), 6);
  // The measure: the largest piece against the mean, and the sum of the pieces' box volumes
  // against the whole box's (1 for a partition by space, up to the number of ranks for
  // interleaved pieces).
  double total = 0.0, largest = 0.0, volumes = 0.0;
  double whole[6] = { HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL };
  int lowestWithPoints = -1;
  for (int r = 0; r < this->Size; ++r)
  {
    total += counts[r];
    largest = std::max(largest, counts[r]);
    if (counts[r] > 0)
    {
      lowestWithPoints = lowestWithPoints < 0 ? r : lowestWithPoints;
      for (int d = 0; d < 3; ++d)
      {
        whole[2 * d] = std::min(whole[2 * d], boxes[6 * r + 2 * d]);
        whole[2 * d + 1] = std::max(whole[2 * d + 1], boxes[6 * r + 2 * d + 1]);
      }
    }
  }
  auto volume = [&](const double* box) {
    double v = 1.0;
    for (int d = 0; d < 3; ++d)
    {
      // Padded by a millionth of the whole box, so that flat pieces still compare.
      const double pad = 1e-6 * (whole[2 * d + 1] - whole[2 * d]) + 1e-300;
      v *= box[2 * d + 1] - box[2 * d] + pad;
    }
    return v;
  };
  for (int r = 0; r < this->Size; ++r)
  {
    volumes += counts[r] > 0 ? volume(&boxes[6 * r]) : 0.0;
  }
  const double imbalance = largest / (total / this->Size);
  const double overlap = volumes / volume(whole);

  // The readers' markers (which arrays are density, mass, smoothing length; the kernel; the
  // periodic box) travel as field data: every rank takes those of the lowest rank with points.
  vtkNew<vtkPolyData> markers;
  if (this->Rank == lowestWithPoints)
  {
    markers->GetFieldData()->ShallowCopy(input->GetFieldData());
  }
  this->Controller->Broadcast(markers, std::max(0, lowestWithPoints));

  // The piece is the input itself (a shallow copy, so that its field data can be replaced), or
  // the redistributed particles.
  vtkSmartPointer<vtkPointSet> source = input;
  const bool redistribute = imbalance > 1.5 || overlap > 1.5;
  if (redistribute)
  {
    source = this->SpreadBySpace(input);
    if (!source)
    {
      report = "a rank's particles did not arrive whole when they were spread by space";
      return nullptr;
    }
    std::ostringstream why;
    why << "redistributed by space: the largest piece held " << imbalance
        << " times the mean, the pieces' boxes " << overlap << " times the whole volume";
    report = why.str();
  }
  vtkSmartPointer<vtkPointSet> piece = vtk::TakeSmartPointer(source->NewInstance());
  piece->ShallowCopy(source);
  vtkNew<vtkFieldData> fieldData;
  fieldData->ShallowCopy(markers->GetFieldData());
  piece->SetFieldData(fieldData);
  return piece;
}

vtkSmartPointer<vtkPointSet> Distribution::SpreadBySpace(vtkPointSet* input)
{
  // A sample of each rank's particles (evenly by index, each weighted by the particles it
  // stands for), the same on every rank, cut into one part per rank.
  constexpr vtkIdType SamplesPerRank = 4096;
  const vtkIdType n = input->GetNumberOfPoints();
  const vtkIdType taken = std::min(n, SamplesPerRank);
  std::vector<double> sample;
  sample.reserve(static_cast<std::size_t>(4 * taken));
  for (vtkIdType k = 0; k < taken; ++k)
  {
    const double* x = input->GetPoint(k * n / taken);
    sample.insert(sample.end(), { x[0], x[1], x[2], static_cast<double>(n) / taken });
  }
  this->GatherAll(sample);
  std::vector<double> xyz, weights;
  for (std::size_t k = 0; k + 3 < sample.size(); k += 4)
  {
    xyz.insert(xyz.end(), { sample[k], sample[k + 1], sample[k + 2] });
    weights.push_back(sample[k + 3]);
  }
  const SpatialPartition partition(xyz, weights, this->Size);

  // Each particle to its part's rank, with every point array and the coordinates as they are
  // (ParaView's vtkDistributedPointCloudFilter stores them as floats and drops the global ids).
  const std::size_t size = static_cast<std::size_t>(this->Size);
  std::vector<std::vector<vtkIdType>> to(size);
  for (vtkIdType j = 0; j < n; ++j)
  {
    to[static_cast<std::size_t>(partition.PartOf(input->GetPoint(j)))].push_back(j);
  }
  std::vector<char> partners;
  const std::vector<double> counts = this->CountsSent(to, partners);
  std::vector<vtkSmartPointer<vtkPolyData>> pieces(size);
  pieces[static_cast<std::size_t>(this->Rank)] =
    PointsOf(input, &to[static_cast<std::size_t>(this->Rank)]);
  bool received = true; // every piece arrived, with the particles its sender counted
  this->WithEachPartner(partners, [&](int other, bool sendFirst) {
    auto send = [&]() {
      vtkSmartPointer<vtkPolyData> piece = PointsOf(input, &to[other]);
      this->Controller->Send(piece, other, SpreadTag);
    };
    auto receive = [&]() {
      pieces[other] = vtkSmartPointer<vtkPolyData>::New();
      const double expected =
        counts[static_cast<std::size_t>(other) * size + static_cast<std::size_t>(this->Rank)];
      received = this->Controller->Receive(pieces[other], other, SpreadTag) != 0 &&
        static_cast<double>(pieces[other]->GetNumberOfPoints()) == expected && received;
    };
    sendFirst ? (send(), receive()) : (receive(), send());
  });
  if (!this->All(received))
  {
    return nullptr;
  }
  // In rank order, from the first piece with points (Concatenated takes its arrays).
  std::vector<vtkSmartPointer<vtkPolyData>> joined;
  for (const auto& piece : pieces)
  {
    if (piece && piece->GetNumberOfPoints() > 0)
    {
      joined.push_back(piece);
    }
  }
  return joined.empty() ? PointsOf(nullptr, nullptr) : Concatenated(joined);
}

vtkSmartPointer<vtkPointSet> Distribution::GatheredOnFirst(vtkPointSet* input)
{
  const CommunicationTimer timer(this->CommunicationSeconds);
  vtkSmartPointer<vtkPolyData> mine = PointsOf(input, nullptr);
  if (this->Rank != 0)
  {
    this->Controller->Send(mine, 0, GatherTag);
    return PointsOf(nullptr, nullptr);
  }
  std::vector<vtkSmartPointer<vtkPolyData>> pieces = { mine };
  for (int r = 1; r < this->Size; ++r)
  {
    auto piece = vtkSmartPointer<vtkPolyData>::New();
    this->Controller->Receive(piece, r, GatherTag);
    pieces.push_back(piece);
  }
  // Concatenated takes the arrays and the field data (the markers) of its first piece: put the
  // first piece with points first (an empty piece may carry neither).
  for (std::size_t r = 0; r < pieces.size(); ++r)
  {
    if (pieces[r]->GetNumberOfPoints() > 0)
    {
      std::swap(pieces.front(), pieces[r]);
      break;
    }
  }
  return Concatenated(pieces);
}

vtkSmartPointer<vtkPolyData> Distribution::WithGhosts(vtkPointSet* owned, const double reachBox[6],
  const std::vector<double>& support, std::vector<double>& values, std::string& problem)
{
  const CommunicationTimer timer(this->CommunicationSeconds);
  const vtkIdType n = owned->GetNumberOfPoints();
  this->OwnedCount = n;
  double* box = this->ReachBox;
  std::copy(reachBox, reachBox + 6, box);
  const std::size_t size = static_cast<std::size_t>(this->Size);
  std::vector<double> boxes(6 * size);
  this->Controller->AllGather(box, boxes.data(), 6);

  // What goes where: every owned sample in another rank's box, or whose support reaches it.
  this->SentIds.assign(size, {});
  this->ReceivedIds.assign(size, {});
  for (vtkIdType j = 0; j < n; ++j)
  {
    const double* x = owned->GetPoint(j);
    const double within = support.empty() ? 0.0 : support[j];
    for (int other = 0; other < this->Size; ++other)
    {
      if (other != this->Rank && BoxDistance(x, &boxes[6 * other]) <= within)
      {
        this->SentIds[other].push_back(j);
      }
    }
  }
  const std::vector<double> allCounts = this->CountsSent(this->SentIds, this->Partners);

  // Room for the ghosts after the owned samples, in rank order; each partner's message is
  // read straight into its place.
  std::vector<vtkIdType> firstOf(size, 0);
  vtkIdType next = n;
  for (std::size_t r = 0; r < size; ++r)
  {
    firstOf[r] = next;
    const auto count = static_cast<vtkIdType>(allCounts[r * size + this->Rank]);
    for (vtkIdType k = 0; k < count; ++k)
    {
      this->ReceivedIds[r].push_back(next + k);
    }
    next += count;
  }
  this->GhostCount = next - n;
  vtkSmartPointer<vtkPolyData> all = WithRoomForGhosts(owned, next);
  values.resize(static_cast<std::size_t>(next));
  std::string local;
  this->WithEachPartner(this->Partners, [&](int other, bool sendFirst) {
    auto send = [&]() {
      if (!this->SentIds[other].empty())
      {
        const std::vector<char> message = GhostMessage(owned, values, this->SentIds[other]);
        const auto bytes = static_cast<vtkIdType>(message.size());
        this->Controller->Send(&bytes, 1, other, GhostTag);
        this->Controller->Send(message.data(), bytes, other, GhostTag);
      }
    };
    auto receive = [&]() {
      if (!this->ReceivedIds[other].empty())
      {
        vtkIdType bytes = 0;
        this->Controller->Receive(&bytes, 1, other, GhostTag);
        std::vector<char> message(static_cast<std::size_t>(std::max<vtkIdType>(bytes, 0)));
        this->Controller->Receive(message.data(), bytes, other, GhostTag);
        std::string why; // (this rank's; `problem` is every rank's, decided below)
        if (!ReadGhostMessage(message, all, firstOf[other], values, why) && local.empty())
        {
          local = "rank " + std::to_string(this->Rank) + " received " + why + " from rank " +
            std::to_string(other) + ".";
        }
      }
    };
    sendFirst ? (send(), receive()) : (receive(), send());
  });
  problem = this->FirstProblem(local);
  return problem.empty() ? all : nullptr;
}

void Distribution::Attach(const Neighborhoods& geometry)
{
  const std::size_t n = geometry.NumberOfSamples;
  std::vector<std::uint32_t> storageOf(n);
  for (std::size_t s = 0; s < n; ++s)
  {
    storageOf[geometry.Order[s]] = static_cast<std::uint32_t>(s);
  }
  this->OwnedSamples.assign(n, 0);
  geometry.Truncated.assign(n, 0);
  // A ghost's neighbourhood is whole only if its ball lies in the reach box, inside which this
  // rank holds every sample. Most ghosts lie deeper in the box than a bound on their radius
  // (RadiusBound, no search): only the others need their lists, computed in parallel.
  auto ballOutside = [&](std::size_t s, double r) {
    const double* x = geometry.Position(s);
    for (int d = 0; d < 3; ++d)
    {
      if (x[d] - r < this->ReachBox[2 * d] || x[d] + r > this->ReachBox[2 * d + 1])
      {
        return true;
      }
    }
    return false;
  };
  const std::vector<std::uint32_t> near = IndicesWhere<std::uint32_t>(n, [&](std::size_t s) {
    return static_cast<vtkIdType>(geometry.Order[s]) >= this->OwnedCount &&
      ballOutside(s, RadiusBound(geometry, s) * (1.0 + 1e-9));
  });
  geometry.EnsureNeighbors(near);
  for (const std::uint32_t s : near)
  {
    geometry.Truncated[s] = ballOutside(s, geometry.RadiusOf(s)) ? 1 : 0;
  }
  for (std::size_t s = 0; s < n; ++s)
  {
    this->OwnedSamples[s] = static_cast<vtkIdType>(geometry.Order[s]) < this->OwnedCount;
  }
  auto inStorageOrder = [&](const std::vector<std::vector<vtkIdType>>& ids) {
    std::vector<std::vector<std::uint32_t>> samples(ids.size());
    for (std::size_t r = 0; r < ids.size(); ++r)
    {
      for (vtkIdType id : ids[r])
      {
        samples[r].push_back(storageOf[id]);
      }
    }
    return samples;
  };
  this->SentSamples = inStorageOrder(this->SentIds);
  this->ReceivedSamples = inStorageOrder(this->ReceivedIds);
}

template <typename Combine>
void Distribution::Trade(std::vector<double>& perSample,
  const std::vector<std::vector<std::uint32_t>>& from,
  const std::vector<std::vector<std::uint32_t>>& to, int tag, Combine&& combine) const
{
  const CommunicationTimer timer(this->CommunicationSeconds);
  if (this->Size <= 1)
  {
    return;
  }
  std::vector<double> buffer;
  this->WithEachPartner(this->Partners, [&](int other, bool sendFirst) {
    auto send = [&]() {
      const std::vector<std::uint32_t>& samples = from[other];
      if (!samples.empty())
      {
        buffer.resize(samples.size());
        for (std::size_t k = 0; k < samples.size(); ++k)
        {
          buffer[k] = perSample[samples[k]];
        }
        this->Controller->Send(buffer.data(), static_cast<vtkIdType>(buffer.size()), other, tag);
      }
    };
    auto receive = [&]() {
      const std::vector<std::uint32_t>& samples = to[other];
      if (!samples.empty())
      {
        buffer.resize(samples.size());
        this->Controller->Receive(buffer.data(), static_cast<vtkIdType>(buffer.size()), other, tag);
        for (std::size_t k = 0; k < samples.size(); ++k)
        {
          perSample[samples[k]] = combine(perSample[samples[k]], buffer[k]);
        }
      }
    };
    sendFirst ? (send(), receive()) : (receive(), send());
  });
}

void Distribution::RefreshGhosts(std::vector<double>& perSample) const
{
  // From the owned samples that were sent, onto their ghost copies.
  this->Trade(perSample, this->SentSamples, this->ReceivedSamples, RefreshTag,
    [](double, double owners) { return owners; });
}

void Distribution::MaxToOwners(std::vector<double>& perSample) const
{
  // From the ghosts here, onto the owned samples whose copies they are.
  this->Trade(perSample, this->ReceivedSamples, this->SentSamples, ToOwnersTag,
    [](double mine, double ghosts) { return std::max(mine, ghosts); });
}

} // namespace lsi
