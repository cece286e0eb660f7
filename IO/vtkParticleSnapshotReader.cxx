// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkParticleSnapshotReader.h"

#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArraySelection.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <numeric>
#include <regex>
#include <utility>

vtkParticleSnapshotReader::vtkParticleSnapshotReader()
{
  this->SetNumberOfInputPorts(0);
  // A changed selection changes the output: re-execute.
  for (vtkDataArraySelection* selection :
    { this->ParticleTypeSelection.Get(), this->PointArraySelection.Get() })
  {
    selection->AddObserver(vtkCommand::ModifiedEvent, this, &vtkParticleSnapshotReader::Modified);
  }
}

vtkParticleSnapshotReader::~vtkParticleSnapshotReader() = default;

void vtkParticleSnapshotReader::SetFileName(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->FileName)
  {
    this->FileName = value;
    this->Modified();
  }
}

int vtkParticleSnapshotReader::GetNumberOfParticleTypeArrays()
{
  return this->ParticleTypeSelection->GetNumberOfArrays();
}

const char* vtkParticleSnapshotReader::GetParticleTypeArrayName(int index)
{
  return this->ParticleTypeSelection->GetArrayName(index);
}

int vtkParticleSnapshotReader::GetParticleTypeArrayStatus(const char* name)
{
  return this->ParticleTypeSelection->ArrayIsEnabled(name);
}

void vtkParticleSnapshotReader::SetParticleTypeStatus(const char* name, int status)
{
  this->ParticleTypeSelection->SetArraySetting(name, status);
}

int vtkParticleSnapshotReader::GetNumberOfPointArrays()
{
  return this->PointArraySelection->GetNumberOfArrays();
}

const char* vtkParticleSnapshotReader::GetPointArrayName(int index)
{
  return this->PointArraySelection->GetArrayName(index);
}

int vtkParticleSnapshotReader::GetPointArrayStatus(const char* name)
{
  return this->PointArraySelection->ArrayIsEnabled(name);
}

void vtkParticleSnapshotReader::SetPointArrayStatus(const char* name, int status)
{
  this->PointArraySelection->SetArraySetting(name, status);
}

void vtkParticleSnapshotReader::WarnOnce(const std::string& message)
{
  if (this->Warned.insert(this->FileName + "\n" + message).second)
  {
    vtkWarningMacro(<< this->FileName << ": " << message);
  }
}

bool vtkParticleSnapshotReader::ReadsArray(const std::string& name)
{
  return !this->PointArraySelection->ArrayExists(name.c_str()) ||
    this->PointArraySelection->ArrayIsEnabled(name.c_str());
}

std::string vtkParticleSnapshotReader::PartTypeName(int number)
{
  static const char* const names[] = { "Gas", "DarkMatter", nullptr, nullptr, "Stars",
    "BlackHoles" };
  const std::string part = "PartType" + std::to_string(number);
  return number >= 0 && number < 6 && names[number] ? std::string(names[number]) + " (" + part + ")"
                                                    : part;
}

std::vector<std::string> vtkParticleSnapshotReader::PartFileNames(
  const std::string& file, long long parts)
{
  static const std::regex numbered(R"((.*)\.([0-9]+)(\.[A-Za-z0-9]+)?$)");
  std::smatch match;
  std::vector<std::string> names;
  if (std::regex_match(file, match, numbered))
  {
    for (long long p = 0; p < parts; ++p)
    {
      names.push_back(match[1].str() + "." + std::to_string(p) + match[3].str());
    }
  }
  return names;
}

bool vtkParticleSnapshotReader::ListPartTypes(const std::vector<long long>& totals,
  const std::vector<std::vector<std::string>>& arrays, std::vector<ParticleType>& types,
  std::vector<int>& numbers, std::string& problem)
{
  types.clear();
  numbers.clear();
  for (std::size_t t = 0; t < totals.size(); ++t)
  {
    if (totals[t] > 0)
    {
      ParticleType type;
      type.Name = PartTypeName(static_cast<int>(t));
      type.Count = totals[t];
      type.Arrays = t < arrays.size() ? arrays[t] : std::vector<std::string>();
      types.push_back(type);
      numbers.push_back(static_cast<int>(t));
    }
  }
  if (types.empty())
  {
    problem = "the snapshot holds no particles";
    return false;
  }
  // Gas, or where there is none the first type there is, so that opening the file shows something.
  types[0].SelectedByDefault = true;
  return true;
}

void vtkParticleSnapshotReader::AddTableMasses(
  vtkPointData* pointData, vtkIdType count, double mass)
{
  vtkNew<vtkDoubleArray> masses;
  masses->SetName("Masses");
  masses->SetNumberOfValues(count);
  masses->Fill(mass);
  pointData->AddArray(masses);
}

vtkNew<vtkCellArray> vtkParticleSnapshotReader::VertexCells(vtkIdType count)
{
  vtkNew<vtkIdTypeArray> ids;
  ids->SetNumberOfValues(count);
  std::iota(ids->Begin(), ids->End(), vtkIdType(0));
  vtkNew<vtkCellArray> cells;
  cells->SetData(1, ids);
  return cells;
}

void vtkParticleSnapshotReader::MarkSPHArrays(vtkPolyData* particles, const SPHMarkers& markers)
{
  vtkFieldData* fields = particles->GetFieldData();
  // An array left unread (PointArraySelection) is not marked.
  auto read = [particles](const std::string& name) {
    return particles->GetPointData()->GetArray(name.c_str()) ? name : std::string();
  };
  const std::string density = read(markers.Density);
  const bool smoothed = !read(markers.SmoothingLength).empty();
  for (const auto& marker : { std::make_pair("DensityArray", density),
         std::make_pair("SmoothingLengthArray", read(markers.SmoothingLength)),
         std::make_pair("MassArray", read(markers.Mass)),
         std::make_pair("SPHKernel", smoothed ? markers.Kernel : std::string()) })
  {
    if (!marker.second.empty())
    {
      vtkNew<vtkStringArray> name;
      name->SetName(marker.first);
      name->InsertNextValue(marker.second);
      fields->AddArray(name);
    }
  }
  if (smoothed)
  {
    vtkNew<vtkDoubleArray> support;
    support->SetName("SupportPerSmoothingLength");
    support->InsertNextValue(markers.SupportPerSmoothingLength);
    fields->AddArray(support);
  }
  if (!density.empty())
  {
    particles->GetPointData()->SetActiveScalars(density.c_str());
  }
}

bool vtkParticleSnapshotReader::UpdateMetaData(bool force)
{
  if (!force && this->MetaDataFileName == this->FileName && this->MetaDataRead)
  {
    return this->MetaDataProblem.empty();
  }
  this->Types.clear();
  this->Time = 0.0;
  this->Fields->Initialize();
  this->MetaDataProblem.clear();
  if (this->FileName.empty())
  {
    this->MetaDataProblem = "no file name";
  }
  else if (!this->ReadMetaData(this->Types, this->Time, this->Fields, this->MetaDataProblem))
  {
    this->Types.clear();
    if (this->MetaDataProblem.empty())
    {
      this->MetaDataProblem = "unreadable";
    }
  }
  this->MetaDataFileName = this->FileName;
  this->MetaDataRead = true;
  // New types and arrays appear with their default (arrays: read); those the user already set
  // keep their setting.
  for (const ParticleType& type : this->Types)
  {
    if (!this->ParticleTypeSelection->ArrayExists(type.Name.c_str()))
    {
      this->ParticleTypeSelection->AddArray(type.Name.c_str(), type.SelectedByDefault);
    }
    for (const std::string& array : type.Arrays)
    {
      if (!this->PointArraySelection->ArrayExists(array.c_str()))
      {
        this->PointArraySelection->AddArray(array.c_str());
      }
    }
  }
  return this->MetaDataProblem.empty();
}

std::vector<std::size_t> vtkParticleSnapshotReader::SelectedTypes()
{
  std::vector<std::size_t> selected;
  for (std::size_t t = 0; t < this->Types.size(); ++t)
  {
    if (this->ParticleTypeSelection->ArrayIsEnabled(this->Types[t].Name.c_str()))
    {
      selected.push_back(t);
    }
  }
  return selected;
}

bool vtkParticleSnapshotReader::ReadShare(
  std::size_t type, int piece, int pieces, vtkPolyData* particles, std::string& problem)
{
  const long long count = this->Types[type].Count;
  const long long begin = count * piece / pieces, end = count * (piece + 1) / pieces;
  this->ParticlesScanned += end - begin;
  // A rank whose share is empty (more ranks than particles of a type) reads nothing.
  return begin >= end || this->ReadParticles(type, begin, end, particles, problem);
}

int vtkParticleSnapshotReader::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

int vtkParticleSnapshotReader::RequestDataObject(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // One selected type: a vtkPolyData; several: a multiblock with one block per type.
  const bool several = this->UpdateMetaData(false) && this->SelectedTypes().size() > 1;
  vtkInformation* info = outputVector->GetInformationObject(0);
  vtkDataObject* output = info->Get(vtkDataObject::DATA_OBJECT());
  const char* wanted = several ? "vtkMultiBlockDataSet" : "vtkPolyData";
  if (!output || !output->IsA(wanted))
  {
    vtkSmartPointer<vtkDataObject> created;
    if (several)
    {
      created = vtkSmartPointer<vtkMultiBlockDataSet>::New();
    }
    else
    {
      created = vtkSmartPointer<vtkPolyData>::New();
    }
    info->Set(vtkDataObject::DATA_OBJECT(), created);
  }
  return 1;
}

int vtkParticleSnapshotReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  info->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  if (!this->UpdateMetaData(true)) // the file may have changed on disk
  {
    return 1; // RequestData reports the problem
  }
  // One time step: the snapshot's own (a series of files gets its steps from the series reader).
  info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), &this->Time, 1);
  const double range[2] = { this->Time, this->Time };
  info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

int vtkParticleSnapshotReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  vtkDataObject* output = info->Get(vtkDataObject::DATA_OBJECT());
  output->Initialize();
  if (!this->UpdateMetaData(false))
  {
    vtkErrorMacro("'" << this->FileName << "': " << this->MetaDataProblem << ".");
    return 0;
  }
  const std::vector<std::size_t> selected = this->SelectedTypes();
  if (selected.empty())
  {
    vtkWarningMacro("'" << this->FileName << "': no particle type selected (ParticleTypes).");
    return 1;
  }
  // This rank's contiguous share of every selected type.
  const int piece = info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    ? info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    : 0;
  const int pieces = info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    ? std::max(1, info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()))
    : 1;
  if (this->ReadRegion &&
    !(this->RegionBounds[0] <= this->RegionBounds[1] &&
      this->RegionBounds[2] <= this->RegionBounds[3] &&
      this->RegionBounds[4] <= this->RegionBounds[5]))
  {
    vtkErrorMacro("'" << this->FileName << "': RegionBounds " << this->RegionBoundsText()
                      << " is not a box: each minimum must be at most its maximum.");
    return 0;
  }
  this->ParticlesScanned = 0;
  vtkMultiBlockDataSet* blocks = vtkMultiBlockDataSet::SafeDownCast(output);
  for (std::size_t k = 0; k < selected.size(); ++k)
  {
    const ParticleType& type = this->Types[selected[k]];
    vtkNew<vtkPolyData> particles;
    std::string problem;
    this->ProgressFrom = static_cast<double>(k) / selected.size();
    this->ProgressTo = static_cast<double>(k + 1) / selected.size();
    const bool read = this->ReadRegion
      ? this->ReadShareInRegion(selected[k], piece, pieces, particles, problem)
      : this->ReadShare(selected[k], piece, pieces, particles, problem);
    if (!read)
    {
      vtkErrorMacro("'" << this->FileName << "', " << type.Name << ": " << problem << ".");
      output->Initialize();
      return 0;
    }
    if (this->ReadRegion && pieces == 1 && particles->GetNumberOfPoints() == 0)
    {
      vtkWarningMacro("'" << this->FileName << "', " << type.Name
                          << ": no particle inside RegionBounds " << this->RegionBoundsText()
                          << ".");
    }
    particles->SetVerts(VertexCells(particles->GetNumberOfPoints()));
    particles->GetFieldData()->PassData(this->Fields);
    if (this->ReadRegion)
    {
      this->AddRegionFields(particles->GetFieldData());
    }
    particles->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), this->Time);
    if (blocks)
    {
      blocks->SetBlock(static_cast<unsigned int>(k), particles);
      blocks->GetMetaData(static_cast<unsigned int>(k))
        ->Set(vtkCompositeDataSet::NAME(), type.Name.c_str());
    }
    else
    {
      output->ShallowCopy(particles);
    }
    this->UpdateProgress(static_cast<double>(k + 1) / selected.size());
    if (this->CheckAbort())
    {
      output->Initialize();
      return 1;
    }
  }
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), this->Time);
  return 1;
}

void vtkParticleSnapshotReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  for (int i = 0; i < this->ParticleTypeSelection->GetNumberOfArrays(); ++i)
  {
    os << indent << "ParticleType " << this->ParticleTypeSelection->GetArrayName(i) << ": "
       << (this->ParticleTypeSelection->GetArraySetting(i) ? "on" : "off") << "\n";
  }
  os << indent << "ReadRegion: " << (this->ReadRegion ? "on" : "off")
     << ", RegionBounds: " << this->RegionBoundsText()
     << ", PeriodicRegion: " << (this->PeriodicRegion ? "on" : "off")
     << ", RegionChunkParticles: " << this->RegionChunkParticles << "\n";
  os << indent << "ParticlesScanned: " << this->ParticlesScanned << "\n";
  for (int i = 0; i < this->PointArraySelection->GetNumberOfArrays(); ++i)
  {
    os << indent << "PointArray " << this->PointArraySelection->GetArrayName(i) << ": "
       << (this->PointArraySelection->GetArraySetting(i) ? "on" : "off") << "\n";
  }
}
