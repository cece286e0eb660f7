// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The readers' tests of a file they must refuse: CanReadFile as expected, an error naming the
// file and the problem, an empty output.
#ifndef RefusedFile_h
#define RefusedFile_h

#include "MessageCounter.h"
#include "TestCheck.h"

#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPointSet.h"

#include <string>

namespace lsi
{
namespace test
{
/// Reads `path` with a new Reader and checks the refusal; `readable`: what CanReadFile should
/// say (true where the problem shows only when reading). Returns the error message.
template <typename Reader>
std::string CheckRefusedFile(const std::string& path, const std::string& expected, bool readable)
{
  Check(Reader::CanReadFile(path.c_str()) == readable,
    path + ": CanReadFile is " + (readable ? "true" : "false"));
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<MessageCounter> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->Update();
  Check(errors->Count > 0 && errors->Last.find(path) != std::string::npos &&
      errors->Last.find(expected) != std::string::npos,
    path + ": an error naming the file and '" + expected + "' (got: " + errors->Last + ")");
  auto* out = vtkPointSet::SafeDownCast(reader->GetOutput());
  Check(!out || out->GetNumberOfPoints() == 0, path + ": empty output");
  return errors->Last;
}
} // namespace test
} // namespace lsi

#endif
