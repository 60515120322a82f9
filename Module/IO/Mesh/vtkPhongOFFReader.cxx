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

// What the first lines of the file say.
struct OFFHeader
{
  bool HasVertexColors = false;
  bool HasVertexNormals = false;
  long long NumberOfVertices = -1;
  long long NumberOfFaces = -1;
};

// The arrays being filled; they become the output only once the whole file has been read,
// so that a bad file leaves an empty output.
struct OFFMesh
{
  vtkNew<vtkPoints> Points;
  vtkNew<vtkFloatArray> Normals;
  vtkNew<vtkUnsignedCharArray> VertexColors;
  vtkNew<vtkCellArray> Polygons;
  std::vector<std::array<unsigned char, 4>> FaceColors;
  bool AnyFaceColor = false;
};

// The reading steps return why the file cannot be read, or an empty string; the reader
// reports it with the file name and the line reached.

// The keyword: OFF with the C (colours) and N (normals) prefixes.
std::string ReadKeyword(OFFLines& lines, OFFHeader& header)
{
  if (!lines.Next())
  {
    return "the file is empty.";
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
    return "not an OFF file (it starts with \"" + quoted +
      (keyword.size() > 32 ? "...\")." : "\").");
  }
  const std::string prefix = keyword.substr(0, keyword.size() - 3);
  if (prefix.find_first_not_of("CN") != std::string::npos)
  {
    return "the OFF variant \"" + keyword + "\" is not supported (OFF, COFF, NOFF, CNOFF).";
  }
  header.HasVertexColors = prefix.find('C') != std::string::npos;
  header.HasVertexNormals = prefix.find('N') != std::string::npos;
  return std::string();
}

// The vertex and face counts, after the keyword on its line or on the next one.
std::string ReadCounts(OFFLines& lines, OFFHeader& header)
{
  std::vector<std::string> counts(lines.Tokens.begin() + 1, lines.Tokens.end());
  if (counts.size() == 1 && counts[0] == "BINARY")
  {
    return "binary OFF is not supported.";
  }
  if (counts.empty())
  {
    if (!lines.Next())
    {
      return "the vertex and face counts are missing.";
    }
    counts = lines.Tokens;
  }
  if (counts.size() < 2 || !ParseIndex(counts[0], header.NumberOfVertices) ||
    !ParseIndex(counts[1], header.NumberOfFaces) || header.NumberOfVertices < 0 ||
    header.NumberOfFaces < 0)
  {
    return "expected the vertex, face and edge counts.";
  }
  return std::string();
}

// The counts are checked against the file's size before anything is allocated from them:
// a vertex takes at least 6 bytes ("0 0 0\n"), a face at least 2 ("0\n"), so a header
// claiming more than the file can hold is refused instead of allocating from it.
std::string CheckCountsAgainstSize(const OFFHeader& header, long long fileSize)
{
  const long long limit = fileSize / 2;
  if (header.NumberOfVertices > limit / 3 || header.NumberOfFaces > limit ||
    6 * header.NumberOfVertices + 2 * header.NumberOfFaces > fileSize)
  {
    return "the header announces " + std::to_string(header.NumberOfVertices) + " vertices and " +
      std::to_string(header.NumberOfFaces) + " faces, more than the file's " +
      std::to_string(fileSize) + " bytes can hold.";
  }
  return std::string();
}

std::string ReadHeader(OFFLines& lines, OFFHeader& header, long long fileSize)
{
  std::string why = ReadKeyword(lines, header);
  why = why.empty() ? ReadCounts(lines, header) : why;
  return why.empty() ? CheckCountsAgainstSize(header, fileSize) : why;
}

void AllocateVertexArrays(const OFFHeader& header, OFFMesh& mesh)
{
  mesh.Points->SetDataTypeToDouble(); // far-away coordinates keep their precision
  mesh.Points->SetNumberOfPoints(header.NumberOfVertices);
  if (header.HasVertexNormals)
  {
    mesh.Normals->SetName("Normals");
    mesh.Normals->SetNumberOfComponents(3);
    mesh.Normals->SetNumberOfTuples(header.NumberOfVertices);
  }
  if (header.HasVertexColors)
  {
    mesh.VertexColors->SetName("Colors");
    mesh.VertexColors->SetNumberOfComponents(4);
    mesh.VertexColors->SetNumberOfTuples(header.NumberOfVertices);
  }
}

// One vertex line: the position, then the normal (NOFF), then the colour (COFF).
std::string ReadVertex(
  const std::vector<std::string>& tokens, const OFFHeader& header, vtkIdType vertex, OFFMesh& mesh)
{
  const size_t expected = 3 + (header.HasVertexNormals ? 3 : 0);
  double values[6];
  if (tokens.size() < expected)
  {
    return "a vertex needs " + std::to_string(expected) + " numbers.";
  }
  for (size_t i = 0; i < expected; ++i)
  {
    if (!ParseDouble(tokens[i], values[i]))
    {
      return "\"" + tokens[i] + "\" is not a number.";
    }
  }
  mesh.Points->SetPoint(vertex, values);
  if (header.HasVertexNormals)
  {
    mesh.Normals->SetTuple(vertex, values + 3);
  }
  if (header.HasVertexColors)
  {
    unsigned char rgba[4];
    if (!ParseColor(tokens, expected, rgba))
    {
      return "a COFF vertex needs a colour of 3 or 4 components.";
    }
    mesh.VertexColors->SetTypedTuple(vertex, rgba);
  }
  return std::string();
}

// The vertices are the first half of the progress, the faces the second.
std::string ReadVertices(
  OFFLines& lines, const OFFHeader& header, OFFMesh& mesh, vtkAlgorithm* algorithm)
{
  AllocateVertexArrays(header, mesh);
  for (vtkIdType vertex = 0; vertex < header.NumberOfVertices; ++vertex)
  {
    if (!lines.Next())
    {
      return "the file ends after " + std::to_string(vertex) + " of " +
        std::to_string(header.NumberOfVertices) + " vertices.";
    }
    const std::string why = ReadVertex(lines.Tokens, header, vertex, mesh);
    if (!why.empty())
    {
      return why;
    }
    if (vertex % 65536 == 0)
    {
      algorithm->UpdateProgress(0.5 * vertex / std::max<long long>(header.NumberOfVertices, 1));
    }
  }
  return std::string();
}

// A face line's vertex count and indices (its colour, if any, follows them).
std::string ReadFaceIndices(
  const std::vector<std::string>& tokens, long long numberOfVertices, std::vector<vtkIdType>& ids)
{
  long long size;
  if (!ParseIndex(tokens[0], size) || size < 0 || tokens.size() < static_cast<size_t>(size) + 1)
  {
    return "a face must give its vertex count and that many vertex indices.";
  }
  ids.resize(size);
  for (long long i = 0; i < size; ++i)
  {
    long long index;
    if (!ParseIndex(tokens[i + 1], index) || index < 0 || index >= numberOfVertices)
    {
      return "vertex index \"" + tokens[i + 1] + "\" does not exist.";
    }
    ids[i] = static_cast<vtkIdType>(index);
  }
  return std::string();
}

// Faces of fewer than three vertices are left out, not refused; skipped counts them for the
// reader's warning.
std::string ReadFaces(OFFLines& lines, const OFFHeader& header, OFFMesh& mesh, vtkIdType& skipped,
  vtkAlgorithm* algorithm)
{
  std::vector<vtkIdType> ids;
  for (long long face = 0; face < header.NumberOfFaces; ++face)
  {
    if (!lines.Next())
    {
      return "the file ends after " + std::to_string(face) + " of " +
        std::to_string(header.NumberOfFaces) + " faces.";
    }
    const std::string why = ReadFaceIndices(lines.Tokens, header.NumberOfVertices, ids);
    if (!why.empty())
    {
      return why;
    }
    const long long size = static_cast<long long>(ids.size());
    if (size < 3)
    {
      ++skipped;
      continue;
    }
    std::array<unsigned char, 4> rgba = { 255, 255, 255, 255 };
    if (ParseColor(lines.Tokens, static_cast<size_t>(size) + 1, rgba.data()))
    {
      mesh.AnyFaceColor = true;
    }
    mesh.Polygons->InsertNextCell(size, ids.data());
    mesh.FaceColors.push_back(rgba);
    if (face % 65536 == 0)
    {
      algorithm->UpdateProgress(0.5 + 0.5 * face / std::max<long long>(header.NumberOfFaces, 1));
    }
  }
  return std::string();
}

// Face colours become cell scalars only when some face has one, so that a file without them
// keeps the material's colour.
void MoveToOutput(const OFFHeader& header, OFFMesh& mesh, vtkPolyData* output)
{
  output->SetPoints(mesh.Points);
  output->SetPolys(mesh.Polygons);
  if (header.HasVertexNormals)
  {
    output->GetPointData()->SetNormals(mesh.Normals);
  }
  if (header.HasVertexColors)
  {
    output->GetPointData()->SetScalars(mesh.VertexColors);
  }
  if (mesh.AnyFaceColor)
  {
    vtkNew<vtkUnsignedCharArray> faceColors;
    faceColors->SetName("Colors");
    faceColors->SetNumberOfComponents(4);
    faceColors->SetNumberOfTuples(static_cast<vtkIdType>(mesh.FaceColors.size()));
    for (vtkIdType i = 0; i < static_cast<vtkIdType>(mesh.FaceColors.size()); ++i)
    {
      faceColors->SetTypedTuple(i, mesh.FaceColors[i].data());
    }
    output->GetCellData()->SetScalars(faceColors);
  }
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
  std::ifstream input(this->FileName, std::ios::binary | std::ios::ate);
  if (!input)
  {
    vtkErrorMacro("Cannot open " << this->FileName << ".");
    return 0;
  }
  const long long fileSize = static_cast<long long>(input.tellg());
  input.seekg(0);
  OFFLines lines(input);
  OFFHeader header;
  OFFMesh mesh;
  std::string why = ReadHeader(lines, header, fileSize);
  if (why.empty())
  {
    why = ReadVertices(lines, header, mesh, this);
  }
  if (why.empty())
  {
    why = ReadFaces(lines, header, mesh, this->NumberOfSkippedFaces, this);
  }
  if (!why.empty())
  {
    vtkErrorMacro(<< this->FileName << ", line " << lines.LineNumber << ": " << why);
    output->Initialize();
    return 0;
  }
  if (this->NumberOfSkippedFaces)
  {
    vtkWarningMacro(<< this->FileName << ": skipped " << this->NumberOfSkippedFaces
                    << " faces with fewer than three vertices.");
  }
  MoveToOutput(header, mesh, output);
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
