#include "vtkLevelSetIsosurface.h"

#include "AutomaticParameters.h"
#include "LevelSetEvolution.h"
#include "LevelSetInitialization.h"
#include "LevelSetIsopoints.h"
#include "LevelSetNeighborCache.h"
#include "LevelSetNeighborhoods.h"
#include "LevelSetSplatOutput.h"
#include "LevelSetSurfaceAttributes.h"
#include "LevelSetTiming.h"
#include "LevelSetVertexCells.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"

#include <algorithm>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkLevelSetIsosurface);

namespace
{
using lsi::Clock;
using lsi::SecondsSince;

vtkNew<vtkTable> EmptyConvergenceTable()
{
  vtkNew<vtkTable> table;
  for (const char* name : { "Iteration", "SignMismatch", "MaxGradientDeviation",
         "MeanGradientDeviation", "BandSize", "Seconds" })
  {
    vtkNew<vtkDoubleArray> column;
    column->SetName(name);
    table->AddColumn(column);
  }
  return table;
}

void AppendRow(vtkTable* table, const lsi::IterationRecord& r)
{
  const double values[6] = { static_cast<double>(r.Iteration), r.SignMismatch,
    r.MaxGradientDeviation, r.MeanGradientDeviation, static_cast<double>(r.BandSize), r.Seconds };
  for (int c = 0; c < 6; ++c)
  {
    vtkDoubleArray::SafeDownCast(table->GetColumn(c))->InsertNextValue(values[c]);
  }
}

// Mean neighbourhood radius h_i over the samples that have a neighbour on the other side of
// the isovalue (all samples if there is none).
double MeanRadiusAtCrossings(const lsi::Neighborhoods& geometry, const std::vector<double>& sign)
{
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < geometry.NumberOfSamples; ++i)
  {
    const std::uint32_t* ids = geometry.NeighborsOf(i);
    for (int m = 1; m < geometry.Stride; ++m)
    {
      if (sign[ids[m]] != sign[i])
      {
        sum += geometry.Radius[i];
        ++count;
        break;
      }
    }
  }
  return count ? sum / count : geometry.MeanRadius;
}

// Signed distance to the inside of the axis-aligned box `bounds` (positive inside).
double DistanceInsideBox(const double x[3], const double bounds[6])
{
  double d = VTK_DOUBLE_MAX;
  for (int k = 0; k < 3; ++k)
  {
    d = std::min(d, std::min(x[k] - bounds[2 * k], bounds[2 * k + 1] - x[k]));
  }
  return d;
}
} // namespace

struct vtkLevelSetIsosurface::Internals
{
  lsi::NeighborCache Cache;
};

vtkLevelSetIsosurface::vtkLevelSetIsosurface()
  : Internal(new Internals)
{
  this->SetNumberOfOutputPorts(3);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

vtkLevelSetIsosurface::~vtkLevelSetIsosurface() = default;

void vtkLevelSetIsosurface::AddAdditionalSeed(double cx, double cy, double cz, double radius)
{
  this->AdditionalSeeds.insert(this->AdditionalSeeds.end(), { cx, cy, cz, radius });
  this->Modified();
}

void vtkLevelSetIsosurface::RemoveAllAdditionalSeeds()
{
  if (!this->AdditionalSeeds.empty())
  {
    this->AdditionalSeeds.clear();
    this->Modified();
  }
}

int vtkLevelSetIsosurface::GetNumberOfAdditionalSeeds() const
{
  return static_cast<int>(this->AdditionalSeeds.size() / 4);
}

int vtkLevelSetIsosurface::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkLevelSetIsosurface::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 2 ? "vtkTable" : "vtkPolyData");
  return 1;
}

int vtkLevelSetIsosurface::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* isopoints = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* particles = vtkPolyData::GetData(outputVector, 1);
  vtkTable* convergence = vtkTable::GetData(outputVector, 2);
  isopoints->Initialize();
  particles->Initialize();
  convergence->Initialize();
  if (!input)
  {
    vtkErrorMacro("Input is not a vtkPointSet.");
    return 0;
  }
  bool ok = false;
  // VTK's global SMP backend may be Sequential (as in ParaView 5.11): run our loops on
  // std::threads regardless, without touching the global state.
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ this->NumberOfThreads, "STDThread", false },
    [&]() { ok = this->Execute(input, isopoints, particles, convergence); });
  if (!ok)
  {
    isopoints->Initialize();
    particles->Initialize();
    convergence->Initialize();
    return this->GetAbortExecute() ? 1 : 0;
  }
  return 1;
}

bool vtkLevelSetIsosurface::Execute(
  vtkPointSet* input, vtkPolyData* isopointOutput, vtkPolyData* particleOutput, vtkTable* table)
{
  // Each stage reports its progress over its own part of [0, 1] and checks for abort between
  // blocks of work (every few tens of milliseconds).
  const lsi::AbortCheck progressOrAbort = [this](double p) { return this->ProgressOrAbort(p); };
  auto stage = [&progressOrAbort](double from, double to) {
    return lsi::SubRange(progressOrAbort, from, to);
  };
  this->NumberOfIterationsPerformed = 0;
  this->Converged = false;

  // --- Validate the input -------------------------------------------------------------
  const vtkIdType n = input->GetNumberOfPoints();
  if (n == 0 || !input->GetPoints())
  {
    vtkErrorMacro("The input has no points.");
    return false;
  }
  if (n < this->NumberOfNeighbors + 1)
  {
    vtkErrorMacro("The input has " << n << " points, fewer than NumberOfNeighbors + 1 = "
                                   << this->NumberOfNeighbors + 1 << ".");
    return false;
  }
  if (n >= static_cast<vtkIdType>(UINT32_MAX))
  {
    vtkErrorMacro("The input has " << n << " points; at most 2^32 - 1 are supported.");
    return false;
  }
  int association = -1;
  vtkDataArray* scalars = this->GetInputArrayToProcess(0, input, association);
  if (!scalars)
  {
    vtkErrorMacro("No input scalars: select a point array with Scalars "
                  "(SetInputArrayToProcess).");
    return false;
  }
  if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    vtkErrorMacro("The array '" << (scalars->GetName() ? scalars->GetName() : "")
                                << "' is not a point array.");
    return false;
  }
  if (scalars->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro("The array '" << (scalars->GetName() ? scalars->GetName() : "") << "' has "
                                << scalars->GetNumberOfComponents()
                                << " components; a scalar (1 component) is required.");
    return false;
  }
  std::vector<double> values(n);
  double range[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
  for (vtkIdType i = 0; i < n; ++i)
  {
    values[i] = scalars->GetComponent(i, 0);
    if (!std::isfinite(values[i]))
    {
      vtkErrorMacro("The array '" << scalars->GetName() << "' has a NaN or infinite value at point "
                                  << i << ".");
      return false;
    }
    range[0] = std::min(range[0], values[i]);
    range[1] = std::max(range[1], values[i]);
    double x[3];
    input->GetPoint(i, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      vtkErrorMacro("Point " << i << " has a NaN or infinite coordinate.");
      return false;
    }
  }
  if (!(this->IsoValue > range[0] && this->IsoValue < range[1]))
  {
    vtkErrorMacro("IsoValue " << this->IsoValue << " is outside the open range of the data ("
                              << range[0] << ", " << range[1] << "): no isosurface.");
    return false;
  }
  for (std::size_t s = 0; s < this->AdditionalSeeds.size(); s += 4)
  {
    if (!(this->AdditionalSeeds[s + 3] > 0.0))
    {
      vtkErrorMacro("Additional seed " << s / 4 << " has radius " << this->AdditionalSeeds[s + 3]
                                       << "; radii must be positive.");
      return false;
    }
  }

  // --- Neighbourhoods: built once per geometry, kept while only parameters change ------
  if (this->ProgressOrAbort(0.02))
  {
    return false;
  }
  auto start = Clock::now();
  vtkPoints* points = input->GetPoints();
  bool searched = false;
  const lsi::Neighborhoods* cached = this->Internal->Cache.Get(points, this->NumberOfNeighbors,
    static_cast<std::size_t>(this->NeighborCacheSize), stage(0.02, 0.35), searched);
  if (!cached)
  {
    return false;
  }
  if (searched)
  {
    ++this->NeighborSearchCount;
    this->NeighborSearchSeconds = SecondsSince(start);
    this->SpatialSortSeconds = cached->SortSeconds;
    this->NearestNeighborSeconds = cached->SearchSeconds;
    this->TreeBuildSeconds = cached->TreeSeconds;
  }
  const lsi::Neighborhoods& geometry = *cached;
  if (geometry.DuplicateSamples > 0)
  {
    vtkErrorMacro("The input has " << geometry.DuplicateSamples
                                   << " points that coincide with another point (for example point "
                                   << geometry.FirstDuplicate
                                   << "). Merge duplicate points first, e.g. with Clean.");
    return false;
  }
  if (geometry.Flat)
  {
    vtkErrorMacro("All input points lie on one plane or line, so the MLS fit is singular "
                  "everywhere: the method needs volume (3D) samples.");
    return false;
  }
  if (this->ProgressOrAbort(0.35))
  {
    return false;
  }

  // --- The data in storage (spatial) order, and the sampling scale where the surface is --
  std::vector<double> offsets(n), dataSign(n); // f - f_iso and its sign
  for (vtkIdType i = 0; i < n; ++i)
  {
    offsets[i] = values[geometry.Order[i]] - this->IsoValue;
    dataSign[i] = lsi::Sign(offsets[i]);
  }
  // Adaptive data (SPH) is sampled far more densely in some places than at the isosurface:
  // every length scale (eps, time step, band, cells) comes from the samples that straddle it.
  const double surfaceRadius = MeanRadiusAtCrossings(geometry, dataSign);
  const double spacing =
    lsi::SpacingFromNeighborhoodRadius(surfaceRadius, geometry.Stride - 1);
  this->MeanSampleSpacing = spacing;

  // --- Parameters -------------------------------------------------------------------------
  const lsi::AutomaticChoice automatic = lsi::ChooseParameters(spacing, this->CurvatureWeight);
  lsi::EvolutionSettings settings;
  settings.Coefficients.Epsilon = this->Epsilon > 0.0 ? this->Epsilon : automatic.Epsilon;
  settings.Coefficients.CurvatureEpsilon =
    this->CurvatureEpsilon > 0.0 ? this->CurvatureEpsilon : settings.Coefficients.Epsilon;
  settings.Coefficients.TimeStep = this->TimeStep > 0.0
    ? this->TimeStep
    : lsi::AutomaticTimeStep(settings.Coefficients.Epsilon, this->CurvatureWeight);
  settings.Coefficients.CurvatureWeight = this->CurvatureWeight;
  settings.Method = this->EvolutionScheme == VARIATIONAL_WITHOUT_REINITIALIZATION
    ? lsi::Scheme::WithoutReinitialization
    : this->EvolutionScheme == ROSENTHAL_LINSEN ? lsi::Scheme::RosenthalLinsen
                                                : lsi::Scheme::WithReinitialization;
  settings.MaximumStep = 0.5 * spacing;
  settings.Coefficients.DistanceRegularization =
    settings.Method == lsi::Scheme::WithoutReinitialization ? this->DistanceRegularization : 0.0;
  settings.ReinitializationSteps = this->ReinitializationSteps;
  settings.ReinitializationTimeStep = automatic.ReinitializationTimeStep;
  settings.Spacing = spacing;
  settings.NeighborhoodRadius = surfaceRadius;
  settings.MaximumIterations = this->MaximumNumberOfIterations;
  settings.ConvergenceTolerance = this->ConvergenceTolerance;
  this->EffectiveEpsilon = settings.Coefficients.Epsilon;
  this->EffectiveCurvatureEpsilon = settings.Coefficients.CurvatureEpsilon;
  this->EffectiveTimeStep = settings.Coefficients.TimeStep;

  // --- Initial level set: signed distance to the union of the seed spheres, cut to the data's
  // bounding box (grown by half a spacing) so that a seed larger than the data still has a
  // front. SeedRadius 0 seeds the whole box; a negative one means a tenth of the largest extent.
  double bounds[6];
  input->GetBounds(bounds);
  const double seedRadius = this->SeedRadius >= 0.0
    ? this->SeedRadius
    : 0.1 * std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  for (int k = 0; k < 3; ++k)
  {
    bounds[2 * k] -= 0.5 * spacing;
    bounds[2 * k + 1] += 0.5 * spacing;
  }
  std::vector<double> spheres;
  if (seedRadius > 0.0)
  {
    spheres.insert(spheres.end(),
      { this->SeedCenter[0], this->SeedCenter[1], this->SeedCenter[2], seedRadius });
    spheres.insert(spheres.end(), this->AdditionalSeeds.begin(), this->AdditionalSeeds.end());
  }
  start = Clock::now();
  std::vector<vtkIdType> samplesInSphere(spheres.size() / 4, 0);
  std::vector<double> phi(n), seedDistance(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double* x = geometry.Position(i);
    double seed = spheres.empty() ? VTK_DOUBLE_MAX : -VTK_DOUBLE_MAX;
    for (std::size_t s = 0; s < spheres.size(); s += 4)
    {
      const double d = spheres[s + 3] -
        std::sqrt((x[0] - spheres[s]) * (x[0] - spheres[s]) +
          (x[1] - spheres[s + 1]) * (x[1] - spheres[s + 1]) +
          (x[2] - spheres[s + 2]) * (x[2] - spheres[s + 2]));
      samplesInSphere[s / 4] += d > 0.0;
      seed = std::max(seed, d);
    }
    seedDistance[i] = seed;
    phi[i] = std::min(seed, DistanceInsideBox(x, bounds));
  }
  for (std::size_t s = 0; s < samplesInSphere.size(); ++s)
  {
    if (samplesInSphere[s] == 0)
    {
      vtkErrorMacro("Seed sphere " << s << (s == 0 ? " (the main seed)" : " (additional)")
                                   << " at (" << spheres[4 * s] << ", " << spheres[4 * s + 1]
                                   << ", " << spheres[4 * s + 2] << ") with radius "
                                   << spheres[4 * s + 3]
                                   << " contains no sample. (In a script, update the input "
                                      "before creating the filter, or set SeedCenter.)");
      return false;
    }
  }
  if (this->Initialization == FLOOD)
  {
    std::vector<char> inSeed(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      inSeed[i] = spheres.empty() || seedDistance[i] > 0.0;
    }
    const lsi::FloodResult flood = lsi::FloodedSignedDistance(geometry, offsets, inSeed,
      static_cast<std::size_t>(geometry.Stride), lsi::ReinitializationHalfWidth(settings),
      phi, stage(0.35, 0.45));
    if (flood.Aborted)
    {
      return false;
    }
    if (flood.SeedSamples == 0)
    {
      vtkErrorMacro("No sample inside the seed sphere(s) has a value above IsoValue "
        << this->IsoValue << ": there is nothing to flood. Move the seed into the object.");
      return false;
    }
  }
  this->InitializationSeconds = SecondsSince(start);

  // --- Evolution --------------------------------------------------------------------------
  start = Clock::now();
  vtkNew<vtkTable> rows = EmptyConvergenceTable();
  lsi::LevelSetEvolution evolution(geometry, dataSign, phi, &offsets);
  const bool finished = evolution.Run(
    settings,
    [&](const lsi::IterationRecord& record) {
      AppendRow(rows, record);
      this->NumberOfIterationsPerformed = record.Iteration;
      // The number of iterations is not known in advance: approach 0.8 (half way after 3).
      return !this->ProgressOrAbort(0.45 + 0.35 * record.Iteration / (record.Iteration + 3.0));
    },
    [this](double) { return this->CheckAbort(); }); // progress comes from the callback above
  this->EvolutionSeconds = SecondsSince(start);
  if (!finished)
  {
    return false;
  }
  this->Converged = evolution.Converged();
  if (this->ProgressOrAbort(0.8))
  {
    return false;
  }

  // --- Isopoints --------------------------------------------------------------------------
  start = Clock::now();
  lsi::IsopointSettings isopointSettings;
  isopointSettings.Completion = this->Completion;
  isopointSettings.CellSize = 0.5 * spacing;
  isopointSettings.Newton.Tolerance = 1e-4 * spacing;
  isopointSettings.Newton.MaximumDistance = 1.0 * spacing;
  lsi::IsopointSet isopoints;
  isopointSettings.RefineOnData = this->DataRefinement;
  isopointSettings.DataMaximumMove = 0.5 * spacing;
  if (!lsi::ExtractIsopoints(
        geometry, phi, offsets, isopointSettings, isopoints, stage(0.8, 0.92)))
  {
    return false;
  }
  this->IsopointSeconds = SecondsSince(start);
  this->CompletionSeconds = isopoints.CompletionSeconds;
  this->DataRefinementSeconds = isopoints.DataRefinementSeconds;
  this->StencilSeconds = geometry.StencilSeconds;
  if (geometry.SingularSamples > 0)
  {
    vtkWarningMacro("The MLS fit was singular at " << geometry.SingularSamples
      << " samples (neighbourhoods on a plane or line); their gradients were taken as zero. "
         "More NumberOfNeighbors may help.");
  }

  // --- Outputs ----------------------------------------------------------------------------
  start = Clock::now();
  vtkNew<vtkPolyData> surface;
  if (!this->SurfaceOutput(input, geometry, isopoints, surface, stage(0.92, 0.98)))
  {
    return false;
  }
  this->NumberOfIsopoints = surface->GetNumberOfPoints();
  if (this->OutputType == SPLATS)
  {
    if (!lsi::MakeSplatPolygons(surface, this->SplatSides, isopointOutput, stage(0.98, 1.0)))
    {
      return false;
    }
  }
  else
  {
    isopointOutput->ShallowCopy(surface);
    isopointOutput->SetVerts(lsi::VertexCells(surface->GetNumberOfPoints()));
  }
  this->OutputSeconds = SecondsSince(start);

  particleOutput->SetPoints(points);
  particleOutput->SetVerts(lsi::VertexCells(n));
  particleOutput->GetPointData()->PassData(input->GetPointData());
  vtkNew<vtkDoubleArray> levelSet;
  levelSet->SetName("LevelSet");
  levelSet->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    levelSet->SetValue(geometry.Order[i], phi[i]); // back from storage order to input order
  }
  particleOutput->GetPointData()->AddArray(levelSet);

  table->ShallowCopy(rows);
  // An abort that arrived during the last stage still empties the outputs.
  return !this->ProgressOrAbort(1.0);
}

bool vtkLevelSetIsosurface::ProgressOrAbort(double progress)
{
  if (progress >= 0.0)
  {
    this->UpdateProgress(progress);
  }
  return this->CheckAbort();
}

bool vtkLevelSetIsosurface::SurfaceOutput(vtkPointSet* input, const lsi::Neighborhoods& geometry,
  const lsi::IsopointSet& isopoints, vtkPolyData* surface, const lsi::AbortCheck& aborted)
{
  const vtkIdType m = static_cast<vtkIdType>(isopoints.Points.size() / 3);
  vtkNew<vtkPoints> coordinates;
  coordinates->SetDataTypeToDouble();
  coordinates->SetNumberOfPoints(m);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(m);
  for (vtkIdType i = 0; i < m; ++i)
  {
    coordinates->SetPoint(i, &isopoints.Points[3 * i]);
    normals->SetTuple(i, &isopoints.Normals[3 * i]);
  }
  surface->SetPoints(coordinates);
  surface->GetPointData()->SetNormals(normals);

  std::vector<double> radii;
  if (!lsi::SplatRadii(isopoints.Points, 6, this->SplatScale, radii, aborted))
  {
    return false;
  }
  vtkNew<vtkFloatArray> radius;
  radius->SetName("SplatRadius");
  radius->SetNumberOfValues(m);
  for (vtkIdType i = 0; i < m; ++i)
  {
    radius->SetValue(i, static_cast<float>(radii[i]));
  }
  surface->GetPointData()->AddArray(radius);

  if (!this->InterpolateArrays)
  {
    return true;
  }
  // Every numeric point array of the input, except names the filter itself produces.
  std::vector<vtkSmartPointer<vtkDataArray>> sources, targets;
  vtkPointData* inputData = input->GetPointData();
  for (int a = 0; a < inputData->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = inputData->GetArray(a);
    if (!array || !array->GetName() || array->GetDataType() == VTK_BIT ||
      surface->GetPointData()->GetArray(array->GetName()))
    {
      continue;
    }
    vtkSmartPointer<vtkDataArray> source = array;
    if (!array->HasStandardMemoryLayout())
    {
      // Read from many threads: only arrays with plain memory are safe for that.
      source = vtkSmartPointer<vtkDoubleArray>::New();
      source->DeepCopy(array);
    }
    vtkSmartPointer<vtkDataArray> target;
    if (array->GetDataType() == VTK_FLOAT)
    {
      target = vtkSmartPointer<vtkFloatArray>::New();
    }
    else
    {
      target = vtkSmartPointer<vtkDoubleArray>::New();
    }
    target->SetName(array->GetName());
    target->SetNumberOfComponents(array->GetNumberOfComponents());
    target->SetNumberOfTuples(m);
    sources.push_back(source);
    targets.push_back(target);
  }
  std::vector<vtkDataArray*> sourceList(sources.begin(), sources.end());
  std::vector<vtkDataArray*> targetList(targets.begin(), targets.end());
  const std::size_t fitCount = 2 * static_cast<std::size_t>(geometry.Stride);
  if (!lsi::InterpolatePointArrays(
        geometry, isopoints.Points, fitCount, sourceList, targetList, aborted))
  {
    return false;
  }
  for (vtkDataArray* target : targetList)
  {
    surface->GetPointData()->AddArray(target);
  }
  // Colour by the isosurface's own scalar by default, as Contour does.
  int association = -1;
  vtkDataArray* scalars = this->GetInputArrayToProcess(0, input, association);
  if (scalars && scalars->GetName() && surface->GetPointData()->GetArray(scalars->GetName()))
  {
    surface->GetPointData()->SetActiveScalars(scalars->GetName());
  }
  return true;
}

void vtkLevelSetIsosurface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IsoValue: " << this->IsoValue << "\n";
  os << indent << "SeedCenter: (" << this->SeedCenter[0] << ", " << this->SeedCenter[1] << ", "
     << this->SeedCenter[2] << ")\n";
  os << indent << "SeedRadius: " << this->SeedRadius << "\n";
  os << indent << "NumberOfAdditionalSeeds: " << this->GetNumberOfAdditionalSeeds() << "\n";
  os << indent << "NumberOfNeighbors: " << this->NumberOfNeighbors << "\n";
  os << indent << "Epsilon: " << this->Epsilon << "\n";
  os << indent << "CurvatureEpsilon: " << this->CurvatureEpsilon << "\n";
  os << indent << "TimeStep: " << this->TimeStep << "\n";
  os << indent << "CurvatureWeight: " << this->CurvatureWeight << "\n";
  os << indent << "ReinitializationSteps: " << this->ReinitializationSteps << "\n";
  os << indent << "DistanceRegularization: " << this->DistanceRegularization << "\n";
  os << indent << "EvolutionScheme: " << this->EvolutionScheme << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->MaximumNumberOfIterations << "\n";
  os << indent << "ConvergenceTolerance: " << this->ConvergenceTolerance << "\n";
 os << indent << "DataRefinement: " << (this->DataRefinement ? "On" : "Off") << "\n";
  os << indent << "Initialization: " << this->Initialization << "\n";
  os << indent << "Completion: " << (this->Completion ? "On" : "Off") << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "OutputType: " << this->OutputType << "\n";
  os << indent << "SplatScale: " << this->SplatScale << "\n";
  os << indent << "SplatSides: " << this->SplatSides << "\n";
  os << indent << "InterpolateArrays: " << (this->InterpolateArrays ? "On" : "Off") << "\n";
  os << indent << "NeighborCacheSize: " << this->NeighborCacheSize << "\n";
  os << indent << "NeighborSearchCount: " << this->NeighborSearchCount << "\n";
  os << indent << "NumberOfIterationsPerformed: " << this->NumberOfIterationsPerformed << "\n";
  os << indent << "Converged: " << this->Converged << "\n";
  os << indent << "MeanSampleSpacing: " << this->MeanSampleSpacing << "\n";
  os << indent << "EffectiveEpsilon: " << this->EffectiveEpsilon << "\n";
  os << indent << "EffectiveCurvatureEpsilon: " << this->EffectiveCurvatureEpsilon << "\n";
  os << indent << "EffectiveTimeStep: " << this->EffectiveTimeStep << "\n";
}
