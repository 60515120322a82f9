#include "vtkPhongOFFReader.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkPhongOFFReader);

namespace
{
// The file as numbered, comment-free, non-empty lines split into tokens.
class OFFLines
{
public:
  explicit OFFLines(std::istream& input)
    : Input(input)
  {
  }

  // The next line with content; false at the end of the file.
  bool Next()
  {
    std::string line;
    while (std::getline(this->Input, line))
    {
      ++this->LineNumber;
      const auto comment = line.find('#');
      if (comment != std::string::npos)
      {
        line.erase(comment);
      }
      this->Tokens.clear();
      std::istringstream words(line);
      std::string word;
      while (words >> word)
      {
        this->Tokens.push_back(word);
      }
      if (!this->Tokens.empty())
      {
        return true;
      }
    }
    return false;
  }

  std::vector<std::string> Tokens;
  int LineNumber = 0;

private:
  std::istream& Input;
};

bool ParseDouble(const std::string& token, double& value)
{
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end != token.c_str() && *end == '\0';
}

bool ParseIndex(const std::string& token, long long& value)
{
  char* end = nullptr;
  value = std::strtoll(token.c_str(), &end, 10);
  return end != token.c_str() && *end == '\0';
}

// Colour components: integers are 0..255, decimals 0..1.
bool ParseColor(const std::vector<std::string>& tokens, size_t first, unsigned char rgba[4])
{
  const size_t count = tokens.size() - first;
  if (count != 3 && count != 4)
  {
    return false;
  }
  const bool decimal = std::any_of(tokens.begin() + first, tokens.end(),
    [](const std::string& token) { return token.find_first_of(".eE") != std::string::npos; });
  rgba[3] = 255;
  for (size_t c = 0; c < count; ++c)
  {
    double value;
    if (!ParseDouble(tokens[first + c], value))
    {
      return false;
    }
    value = decimal ? value * 255.0 : value;
    rgba[c] =
      static_cast<unsigned char>(std::min(std::max(value + (decimal ? 0.5 : 0.0), 0.0), 255.0));
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkPhongOFFReader::vtkPhongOFFReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkPhongOFFReader::~vtkPhongOFFReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
bool vtkPhongOFFReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return false;
  }
  std::ifstream input(fileName);
  OFFLines lines(input);
  if (!input || !lines.Next())
  {
    return false;
  }
  const std::string& keyword = lines.Tokens[0];
  return keyword.size() >= 3 && keyword.compare(keyword.size() - 3, 3, "OFF") == 0;
}

//------------------------------------------------------------------------------
int vtkPhongOFFReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfSkippedFaces = 0;
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName was set.");
    return 0;
  }
  std::ifstream input(this->FileName);
  if (!input)
  {
    vtkErrorMacro("Cannot open " << this->FileName << ".");
    return 0;
  }
  OFFLines lines(input);
  auto fail = [&](const std::string& why)
  {
    vtkErrorMacro(<< this->FileName << ", line " << lines.LineNumber << ": " << why);
    output->Initialize();
    return 0;
  };

  if (!lines.Next())
  {
    return fail("the file is empty.");
  }
  const std::string keyword = lines.Tokens[0];
  if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
  {
    // Quote the start of what was found, printable and short: a binary file's bytes would
    // fill the terminal.
    std::string quoted = keyword.substr(0, 32);
    for (char& c : quoted)
    {
      c = (c >= 32 && c < 127) ? c : '?';
    }
    return fail(
      "not an OFF file (it starts with \"" + quoted + (keyword.size() > 32 ? "...\")." : "\")."));
  }
  const std::string prefix = keyword.substr(0, keyword.size() - 3);
  if (prefix.find_first_not_of("CN") != std::string::npos)
  {
    return fail("the OFF variant \"" + keyword + "\" is not supported (OFF, COFF, NOFF, CNOFF).");
  }
  const bool hasVertexColors = prefix.find('C') != std::string::npos;
  const bool hasVertexNormals = prefix.find('N') != std::string::npos;

  // The counts may follow the keyword on the same line.
  std::vector<std::string> counts(lines.Tokens.begin() + 1, lines.Tokens.end());
  if (counts.size() == 1 && counts[0] == "BINARY")
  {
    return fail("binary OFF is not supported.");
  }
  if (counts.empty())
  {
    if (!lines.Next())
    {
      return fail("the vertex and face counts are missing.");
    }
    counts = lines.Tokens;
  }
  long long numberOfVertices = -1, numberOfFaces = -1;
  if (counts.size() < 2 || !ParseIndex(counts[0], numberOfVertices) ||
    !ParseIndex(counts[1], numberOfFaces) || numberOfVertices < 0 || numberOfFaces < 0)
  {
    return fail("expected the vertex, face and edge counts.");
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble(); // far-away coordinates keep their precision
  points->SetNumberOfPoints(numberOfVertices);
  vtkNew<vtkFloatArray> normals;
  vtkNew<vtkUnsignedCharArray> vertexColors;
  const size_t expected = 3 + (hasVertexNormals ? 3 : 0);
  if (hasVertexNormals)
  {
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(numberOfVertices);
  }
  if (hasVertexColors)
  {
    vertexColors->SetName("Colors");
    vertexColors->SetNumberOfComponents(4);
    vertexColors->SetNumberOfTuples(numberOfVertices);
  }
  for (vtkIdType vertex = 0; vertex < numberOfVertices; ++vertex)
  {
    if (!lines.Next())
    {
      return fail("the file ends after " + std::to_string(vertex) + " of " +
        std::to_string(numberOfVertices) + " vertices.");
    }
    double values[6];
    if (lines.Tokens.size() < expected)
    {
      return fail("a vertex needs " + std::to_string(expected) + " numbers.");
    }
    for (size_t i = 0; i < expected; ++i)
    {
      if (!ParseDouble(lines.Tokens[i], values[i]))
      {
        return fail("\"" + lines.Tokens[i] + "\" is not a number.");
      }
    }
    points->SetPoint(vertex, values);
    if (hasVertexNormals)
    {
      normals->SetTuple(vertex, values + 3);
    }
    if (hasVertexColors)
    {
      unsigned char rgba[4];
      if (!ParseColor(lines.Tokens, expected, rgba))
      {
        return fail("a COFF vertex needs a colour of 3 or 4 components.");
      }
      vertexColors->SetTypedTuple(vertex, rgba);
    }
    if (vertex % 65536 == 0)
    {
      this->UpdateProgress(0.5 * vertex / std::max<long long>(numberOfVertices, 1));
    }
  }

  vtkNew<vtkCellArray> polygons;
  vtkNew<vtkUnsignedCharArray> faceColors;
  faceColors->SetName("Colors");
  faceColors->SetNumberOfComponents(4);
  bool anyFaceColor = false;
  std::vector<vtkIdType> ids;
  std::vector<std::array<unsigned char, 4>> colorOfFace;
  for (long long face = 0; face < numberOfFaces; ++face)
  {
    if (!lines.Next())
    {
      return fail("the file ends after " + std::to_string(face) + " of " +
        std::to_string(numberOfFaces) + " faces.");
    }
    long long size;
    if (!ParseIndex(lines.Tokens[0], size) || size < 0 ||
      lines.Tokens.size() < static_cast<size_t>(size) + 1)
    {
      return fail("a face must give its vertex count and that many vertex indices.");
    }
    ids.resize(size);
    for (long long i = 0; i < size; ++i)
    {
      long long index;
      if (!ParseIndex(lines.Tokens[i + 1], index) || index < 0 || index >= numberOfVertices)
      {
        return fail("vertex index \"" + lines.Tokens[i + 1] + "\" does not exist.");
      }
      ids[i] = static_cast<vtkIdType>(index);
    }
    if (size < 3)
    {
      ++this->NumberOfSkippedFaces;
      continue;
    }
    std::array<unsigned char, 4> rgba = { 255, 255, 255, 255 };
    if (ParseColor(lines.Tokens, static_cast<size_t>(size) + 1, rgba.data()))
    {
      anyFaceColor = true;
    }
    polygons->InsertNextCell(size, ids.data());
    colorOfFace.push_back(rgba);
    if (face % 65536 == 0)
    {
      this->UpdateProgress(0.5 + 0.5 * face / std::max<long long>(numberOfFaces, 1));
    }
  }
  if (this->NumberOfSkippedFaces)
  {
    vtkWarningMacro(<< this->FileName << ": skipped " << this->NumberOfSkippedFaces
                    << " faces with fewer than three vertices.");
  }

  output->SetPoints(points);
  output->SetPolys(polygons);
  if (hasVertexNormals)
  {
    output->GetPointData()->SetNormals(normals);
  }
  if (hasVertexColors)
  {
    output->GetPointData()->SetScalars(vertexColors);
  }
  if (anyFaceColor)
  {
    faceColors->SetNumberOfTuples(static_cast<vtkIdType>(colorOfFace.size()));
    for (vtkIdType i = 0; i < static_cast<vtkIdType>(colorOfFace.size()); ++i)
    {
      faceColors->SetTypedTuple(i, colorOfFace[i].data());
    }
    output->GetCellData()->SetScalars(faceColors);
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkPhongOFFReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "NumberOfSkippedFaces: " << this->NumberOfSkippedFaces << "\n";
}
