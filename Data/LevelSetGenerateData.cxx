// Writes the paper's synthetic test data (§8.2 one-component field, our multi-component field)
// as uniform random samples with the scalar "f", to a binary .vtp (readable by Debian 12's
// ParaView 5.11, which cannot read appended-mode XML).
//   LevelSetGenerateData one-component|multi-component|adaptive-noisy SAMPLES OUTPUT.vtp [RANDOM_SEED]
#include "SyntheticCases.h"
#include "SyntheticParticles.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataWriter.h"

#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

int main(int argc, char* argv[])
{
  if (argc < 4)
  {
    std::cerr << "usage: LevelSetGenerateData one-component|multi-component|adaptive-noisy SAMPLES OUTPUT.vtp "
                 "[RANDOM_SEED]\n";
    return EXIT_FAILURE;
  }
  const std::string name = argv[1];
  std::unique_ptr<lsi::cases::Case> c;
  if (name == "one-component")
  {
    c.reset(new lsi::cases::OneComponentCase);
  }
  else if (name == "multi-component")
  {
    c.reset(new lsi::cases::MultiComponentCase);
  }
  else if (name == "adaptive-noisy")
  {
    c.reset(new lsi::cases::AdaptiveNoisyCase);
  }
  else
  {
    std::cerr << "unknown case " << name << "\n";
    return EXIT_FAILURE;
  }
  const std::size_t count = std::strtoull(argv[2], nullptr, 10);
  const std::uint64_t seed = argc > 4 ? std::strtoull(argv[4], nullptr, 10) : 1;
  const auto samples = c->Samples(count, seed);
  vtkSmartPointer<vtkPolyData> data = lsi::cases::MakeParticles(*c, samples);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(data);
  writer->SetDataModeToBinary();
  writer->SetFileName(argv[3]);
  if (!writer->Write())
  {
    std::cerr << "could not write " << argv[3] << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << count << " samples of the " << name << " case to " << argv[3]
            << " (isovalue " << c->IsoValue << ", seed centre " << c->Seeds[0].Center.transpose()
            << ", radius " << c->Seeds[0].Radius << ")\n";
  return EXIT_SUCCESS;
}
