// vtkPhongAssimpReader on files nobody here wrote: assimp's own test models (Debian's
// assimp-testmodels; the directory is the first argument). An OBJ with its MTL (materials,
// texture path, normals, texture coordinates), PLY colours (8-bit and float), point clouds,
// a COLLADA scene instancing one mesh under two node transforms, an STL, and broken files
// that must give an error and an empty output; glTF files that crash assimp itself (JSON
// nested 200 000 levels deep, a chain of 100 000 nodes, a cycle of nodes, a child that does
// not exist, a GLB whose JSON chunk overruns the file) refused before assimp sees them.

#include "vtkCompositeDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPhongAssimpReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnsignedCharArray.h"

#include "vtkTestUtilities.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
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

struct Result
{
  vtkSmartPointer<vtkMultiBlockDataSet> Blocks;
  bool Error = false;
};

Result Read(const std::string& path, vtkTypeInt64 maxFileSize = vtkTypeInt64(1) << 30)
{
  vtkNew<vtkTest::ErrorObserver> observer;
  vtkNew<vtkPhongAssimpReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->SetFileName(path.c_str());
  reader->SetMaxFileSize(maxFileSize);
  reader->Update();
  return { reader->GetOutput(), observer->GetError() != 0 };
}

vtkPolyData* Block(const Result& result, unsigned int index)
{
  return index < result.Blocks->GetNumberOfBlocks()
    ? vtkPolyData::SafeDownCast(result.Blocks->GetBlock(index))
    : nullptr;
}

std::string BlockName(const Result& result, unsigned int index)
{
  const char* name = result.Blocks->GetMetaData(index)->Get(vtkCompositeDataSet::NAME());
  return name ? name : "";
}

std::string FieldString(vtkPolyData* block, const char* name)
{
  auto* array = vtkStringArray::SafeDownCast(block->GetFieldData()->GetAbstractArray(name));
  return array && array->GetNumberOfValues() ? array->GetValue(0) : "";
}

bool FieldNear(vtkPolyData* block, const char* name, const double* expected, int components)
{
  auto* array = vtkDoubleArray::SafeDownCast(block->GetFieldData()->GetArray(name));
  if (!array || array->GetNumberOfComponents() != components)
  {
    return false;
  }
  for (int c = 0; c < components; ++c)
  {
    if (std::abs(array->GetComponent(0, c) - expected[c]) > 1e-5)
    {
      return false;
    }
  }
  return true;
}

// spider.obj: 19 groups, each with the material spider.mtl gives it.
void CheckObjWithMaterials(const std::string& models)
{
  const Result spider = Read(models + "/OBJ/spider.obj");
  Expect(!spider.Error, "spider.obj reads without error");
  Expect(spider.Blocks->GetNumberOfBlocks() == 19, "spider.obj has 19 blocks");
  vtkPolyData* skin = nullptr;
  for (unsigned int b = 0; b < spider.Blocks->GetNumberOfBlocks(); ++b)
  {
    if (BlockName(spider, b) == "OK/OK")
    {
      skin = Block(spider, b);
    }
  }
  Expect(skin != nullptr, "spider.obj has the block OK/OK");
  if (!skin)
  {
    return;
  }
  const double kd[3] = { 0.827451, 0.792157, 0.772549 }, ka[3] = { 0.2, 0.2, 0.2 };
  const double ns = 0.0;
  Expect(FieldString(skin, "MaterialName") == "Skin", "OK/OK uses the material Skin");
  Expect(FieldNear(skin, "MaterialDiffuse", kd, 3), "Skin's Kd from spider.mtl");
  Expect(FieldNear(skin, "MaterialAmbient", ka, 3), "Skin's Ka from spider.mtl");
  Expect(FieldNear(skin, "MaterialShininess", &ns, 1), "Skin's Ns, as the file gives it");
  const std::string texture = FieldString(skin, "MaterialDiffuseTexture");
  Expect(texture.size() > 17 && texture.substr(texture.size() - 17) == "wal67ar_small.jpg" &&
      texture.find('\\') == std::string::npos && texture[0] == '/',
    "Skin's map_Kd as an absolute path with '/' (got " + texture + ")");
  Expect(skin->GetPointData()->GetNormals() && skin->GetPointData()->GetTCoords(),
    "OK/OK has the file's normals and texture coordinates");
  Expect(skin->GetNumberOfPolys() == 60 && skin->GetNumberOfPoints() == 37,
    "OK/OK: 60 triangles on 37 shared vertices");
}

void CheckColor(vtkPolyData* block, vtkIdType point, const unsigned char* rgba, const char* what)
{
  auto* colors =
    block ? vtkUnsignedCharArray::SafeDownCast(block->GetPointData()->GetScalars()) : nullptr;
  bool same = colors && colors->GetNumberOfComponents() == 4 && point < colors->GetNumberOfTuples();
  for (int c = 0; same && c < 4; ++c)
  {
    same = colors->GetValue(4 * point + c) == rgba[c];
  }
  Expect(same, what);
}

// PLY colours, 8-bit (points.ply, a point cloud) and float (float-color.ply).
void CheckColorsAndPointClouds(const std::string& models)
{
  const Result points = Read(models + "/PLY/points.ply");
  vtkPolyData* cloud = Block(points, 0);
  Expect(!points.Error && cloud && cloud->GetNumberOfVerts() == 4 && cloud->GetNumberOfPolys() == 0,
    "points.ply: a point cloud of 4 verts");
  const unsigned char magenta[4] = { 255, 0, 255, 255 };
  CheckColor(cloud, 1, magenta, "points.ply: vertex 1 is 255 0 255, opaque");
  const Result floats = Read(models + "/PLY/float-color.ply");
  const unsigned char blue[4] = { 0, 0, 255, 255 };
  CheckColor(Block(floats, 0), 2, blue, "float-color.ply: float colour 0 0 1 1 as 0 0 255 255");
  const Result obj = Read(models + "/OBJ/point_cloud.obj");
  vtkPolyData* objCloud = Block(obj, 0);
  Expect(!obj.Error && objCloud && objCloud->GetNumberOfVerts() == 3 &&
      objCloud->GetNumberOfCells() == 3,
    "point_cloud.obj (vertices, no faces): 3 verts");
  const Result lines = Read(models + "/OBJ/testline.obj");
  Expect(Block(lines, 0) && Block(lines, 0)->GetNumberOfLines() == 18 &&
      Block(lines, 0)->GetNumberOfPolys() == 0,
    "testline.obj: 18 lines");
}

// teapot_instancenodes.DAE: one mesh used by two nodes, the second nested in a node translated
// by (-120.80132, 2.58064, 0) inches; the file's unit is the inch (0.0254 m), which assimp
// applies, so the instances are 0.0254 * |(-120.80132, 2.58064)| = 3.069054 m apart.
void CheckNodeTransforms(const std::string& models)
{
  const Result teapots = Read(models + "/Collada/teapot_instancenodes.DAE");
  vtkPolyData* first = Block(teapots, 0);
  vtkPolyData* second = Block(teapots, 1);
  Expect(teapots.Blocks->GetNumberOfBlocks() == 2 && first && second &&
      first->GetNumberOfPoints() == second->GetNumberOfPoints(),
    "teapot_instancenodes.DAE: one mesh, two instances");
  if (!first || !second)
  {
    return;
  }
  double a[3], b[3];
  first->GetCenter(a);
  second->GetCenter(b);
  const double distance = std::sqrt(
    (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
  const double expected = 0.0254 * std::sqrt(120.80132 * 120.80132 + 2.58064 * 2.58064);
  Expect(std::abs(distance - expected) < 1e-4,
    "the instances are " + std::to_string(expected) + " apart (got " + std::to_string(distance) +
      ")");
}

// STL: facet normals dropped, vertices shared, so that normals can be smooth.
void CheckStl(const std::string& models)
{
  const Result stl = Read(models + "/STL/Spider_binary.stl");
  vtkPolyData* mesh = Block(stl, 0);
  Expect(!stl.Error && mesh && mesh->GetNumberOfPolys() > 0 &&
      mesh->GetNumberOfPoints() < mesh->GetNumberOfPolys(),
    "Spider_binary.stl: triangles sharing their vertices");
  Expect(mesh && !mesh->GetPointData()->GetNormals(), "Spider_binary.stl: no facet normals");
}

void CheckBrokenFiles(const std::string& models)
{
  const char* broken[] = { "/invalid/malformed.obj", "/invalid/empty.obj", "/invalid/empty.ply",
    "/OBJ/no-such-file.obj" };
  for (const char* name : broken)
  {
    const Result result = Read(models + name);
    Expect(result.Error, std::string(name) + " is reported as an error");
    Expect(result.Blocks->GetNumberOfBlocks() == 0, std::string(name) + " gives no block");
  }
  const Result tooBig = Read(models + "/OBJ/spider.obj", 1000);
  Expect(
    tooBig.Error && tooBig.Blocks->GetNumberOfBlocks() == 0, "a file over MaxFileSize is refused");
  Expect(vtkPhongAssimpReader::CanReadFile("x.glb") && vtkPhongAssimpReader::CanReadFile("x.OBJ") &&
      !vtkPhongAssimpReader::CanReadFile("x.png"),
    "CanReadFile goes by assimp's extensions");
  Expect(vtkPhongAssimpReader::GetSupportedExtensions().find("*.fbx") != std::string::npos,
    "GetSupportedExtensions lists *.fbx");
}

// A one-triangle glTF whose "nodes" array is `nodes` (one of them names mesh 0), its buffer
// embedded as a data URI.
std::string Gltf(const std::string& nodes)
{
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": )" +
    nodes +
    R"(, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "accessors": [{)"
    R"("bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "max": [1, 1, 0],)"
    R"( "min": [0, 0, 0]}], "bufferViews": [{"buffer": 0, "byteLength": 36}], "buffers": [{)"
    R"("byteLength": 36, "uri": "data:application/octet-stream;base64,)"
    R"(AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})";
}

// Nodes 0 .. count-1, each the parent of the next; the last holds the mesh.
std::string NodeChain(int count)
{
  std::ostringstream nodes;
  nodes << "[";
  for (int i = 0; i < count - 1; ++i)
  {
    nodes << R"({"children": [)" << i + 1 << "]}, ";
  }
  nodes << R"({"mesh": 0}])";
  return nodes.str();
}

std::string WriteFile(const std::string& path, const std::string& bytes)
{
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

std::string ReadText(const std::string& path)
{
  std::ostringstream text;
  text << std::ifstream(path, std::ios::binary).rdbuf();
  return text.str();
}

void CheckGltfStructure(const std::string& models, const std::string& temporary)
{
  const std::string box = models + "/glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf";
  Expect(!Read(box).Error, "assimp's BoxTextured.gltf is read");
  const std::string original = ReadText(box);
  const std::string deep = "[" + std::string(200000, '[') + std::string(200000, ']') + "]";
  const std::pair<std::string, std::string> refused[] = {
    { "deep.gltf", "{\"extras\": " + deep + ", " + original.substr(original.find('{') + 1) },
    { "chain.gltf", Gltf(NodeChain(100000)) },
    { "cycle.gltf", Gltf(R"([{"children": [1], "mesh": 0}, {"children": [0]}])") },
    { "child.gltf", Gltf(R"([{"children": [7], "mesh": 0}])") },
    { "chunk.glb", std::string("glTF\x02\0\0\0\x64\0\0\0\0\xca\x9a\x3bJSON{}", 22) },
  };
  for (const auto& file : refused)
  {
    const Result result = Read(WriteFile(temporary + "/" + file.first, file.second));
    Expect(result.Error && result.Blocks->GetNumberOfBlocks() == 0,
      file.first + " is refused with an error, before assimp reads it");
  }
  // What assimp reads is still read: the deepest chain allowed, and the same nodes shallow.
  const Result chain = Read(WriteFile(temporary + "/chain1024.gltf", Gltf(NodeChain(1024))));
  Expect(!chain.Error && chain.Blocks->GetNumberOfBlocks() == 1, "a chain of 1024 nodes is read");
}
}

int TestPhongAssimpReader(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: TestPhongAssimpReader /usr/share/assimp/models\n";
    return EXIT_FAILURE;
  }
  const std::string models = argv[1];
  std::cout << "assimp " << vtkPhongAssimpReader::GetAssimpVersion() << "\n";
  CheckObjWithMaterials(models);
  CheckColorsAndPointClouds(models);
  CheckNodeTransforms(models);
  CheckStl(models);
  CheckBrokenFiles(models);
  char* temporary =
    vtkTestUtilities::GetArgOrEnvOrDefault("-T", argc, argv, "VTK_TEMP_DIR", "Testing/Temporary");
  const std::string directory = temporary;
  delete[] temporary;
  CheckGltfStructure(models, directory);
  std::cout << (Failures == 0 ? "all checks passed" : "some checks failed") << "\n";
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
