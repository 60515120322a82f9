// vtkPhongOFFReader on a file nobody here wrote (CGAL's fandisk, the first argument) and
// on small files written by the test: colours per vertex and per face, polygons, comments,
// and the broken files that must give an error and an empty output instead of a crash.

#include "vtkCellData.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkPhongOFFReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTestErrorObserver.h"
#include "vtkTestUtilities.h"
#include "vtkUnsignedCharArray.h"

#include <fstream>
#include <iostream>
#include <string>

namespace
{
int Failures = 0;

void Expect(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "FAILED: " << what << "\n";
    ++Failures;
  }
}

std::string WriteFile(const std::string& directory, const char* name, const char* text)
{
  std::string path = directory + "/" + name;
  std::ofstream(path) << text;
  return path;
}

// Reads the file; returns the output and whether the reader reported an error.
vtkSmartPointer<vtkPolyData> Read(const std::string& path, bool& reportedError)
{
  vtkNew<vtkTest::ErrorObserver> observer;
  vtkNew<vtkPhongOFFReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->SetFileName(path.c_str());
  reader->Update();
  reportedError = observer->GetError();
  return reader->GetOutput();
}

void CheckRealMesh(const char* fandisk)
{
  Expect(vtkPhongOFFReader::CanReadFile(fandisk), "CanReadFile accepts fandisk.off");
  bool error = false;
  auto mesh = Read(fandisk, error);
  // The counts of the file's header line: 6475 vertices, 12946 faces.
  Expect(!error, "fandisk.off reads without error");
  Expect(mesh->GetNumberOfPoints() == 6475, "fandisk.off has 6475 points");
  Expect(mesh->GetNumberOfPolys() == 12946, "fandisk.off has 12946 polygons");
}

void CheckColoursAndPolygons(const std::string& directory)
{
  const char* text = "# a coloured quad and triangle\r\n"
                     "COFF\n"
                     "5 2 0\n"
                     "0 0 0 255 0 0 255\n"
                     "1 0 0 0 255 0 255\n"
                     "1 1 0 0 0 255 255\n"
                     "0 1 0 255 255 255 255\n"
                     "2 2 0 0.5 0.5 0.5 1.0\n"
                     "4 0 1 2 3\n"
                     "3 1 4 2 0 0 255\n";
  bool error = false;
  auto mesh = Read(WriteFile(directory, "coloured.off", text), error);
  Expect(!error, "a COFF file with comments and CRLF reads");
  Expect(mesh->GetNumberOfPoints() == 5 && mesh->GetNumberOfPolys() == 2, "5 points, 2 polygons");
  auto* pointColours = vtkUnsignedCharArray::SafeDownCast(mesh->GetPointData()->GetArray("Colors"));
  Expect(pointColours && pointColours->GetNumberOfComponents() == 4, "RGBA point colours");
  if (pointColours)
  {
    Expect(pointColours->GetValue(4) == 0 && pointColours->GetValue(5) == 255,
      "integer components stay in [0, 255]");
    Expect(pointColours->GetValue(16) == 128 || pointColours->GetValue(16) == 127,
      "a decimal component 0.5 becomes half of 255");
  }
  Expect(mesh->GetCellData()->GetArray("Colors") != nullptr, "a face colour becomes cell scalars");
}

void CheckBrokenFiles(const std::string& directory)
{
  const char* broken[][2] = {
    { "not-off.off", "PLY\n3 1 0\n" },
    { "truncated.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n" },
    { "bad-index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1000\n" },
    { "negative-index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n" },
    // assimp's invalid/OutOfMemory.off: counts no file of this size can hold, refused
    // before anything is allocated from them (it used to throw std::bad_alloc).
    { "huge-counts.off", "OFF\n3535352353586 0\n-0.5 -0.5 0.5\n0.5 -0.5 0.5\n" },
    { "too-many-faces.off", "OFF\n3 400000000000 0\n0 0 0\n1 0 0\n0 1 0\n" },
  };
  for (const auto& file : broken)
  {
    bool error = false;
    auto mesh = Read(WriteFile(directory, file[0], file[1]), error);
    Expect(error, std::string(file[0]) + " is reported as an error");
    Expect(mesh->GetNumberOfCells() == 0, std::string(file[0]) + " gives an empty output");
  }
  bool error = false;
  Read(directory + "/does-not-exist.off", error);
  Expect(error, "a missing file is reported");
}
}

int TestPhongOFFReader(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: TestPhongOFFReader fandisk.off [-T temporary-directory]\n";
    return EXIT_FAILURE;
  }
  char* temporary =
    vtkTestUtilities::GetArgOrEnvOrDefault("-T", argc, argv, "VTK_TEMP_DIR", "Testing/Temporary");
  const std::string directory = temporary;
  delete[] temporary;

  CheckRealMesh(argv[1]);
  CheckColoursAndPolygons(directory);
  CheckBrokenFiles(directory);
  std::cout << (Failures == 0 ? "all checks passed" : "some checks failed") << "\n";
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
