// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Counts the error or warning events of a VTK object and keeps the last message, so that tests
// can require a message without printing it:
//   vtkNew<lsi::test::MessageCounter> errors;
//   algorithm->AddObserver(vtkCommand::ErrorEvent, errors);
#ifndef MessageCounter_h
#define MessageCounter_h

#include "vtkCommand.h"

#include <string>

namespace lsi
{
namespace test
{
class MessageCounter : public vtkCommand
{
public:
  static MessageCounter* New() { return new MessageCounter; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    ++this->Count;
    this->Last = static_cast<const char*>(data);
    this->All += this->Last;
  }
  int Count = 0;
  std::string Last;
  std::string All; // every message, one after another
};
} // namespace test
} // namespace lsi

#endif
