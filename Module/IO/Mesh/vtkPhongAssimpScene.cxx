#include "vtkPhongAssimpScene.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>

namespace
{
// assimp's colours are floats, nominally in [0, 1]; VTK's mapper shows 8-bit colours as
// they are. NaN becomes 0, anything outside the range is clamped.
unsigned char ToByte(float value)
{
  if (!(value > 0.0f))
  {
    return 0;
  }
  return static_cast<unsigned char>(std::min(value, 1.0f) * 255.0f + 0.5f);
}

std::string NameOf(const aiString& name)
{
  return std::string(name.C_Str(), name.length);
}

// The points, transformed; doubles, so that the transform loses nothing a float file had.
void SetPoints(const aiMesh& mesh, const aiMatrix4x4& transform, vtkPolyData* polydata)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.mNumVertices);
  for (unsigned int i = 0; i < mesh.mNumVertices; ++i)
  {
    const aiVector3D& v = mesh.mVertices[i];
    const double x = transform.a1 * v.x + transform.a2 * v.y + transform.a3 * v.z + transform.a4;
    const double y = transform.b1 * v.x + transform.b2 * v.y + transform.b3 * v.z + transform.b4;
    const double z = transform.c1 * v.x + transform.c2 * v.y + transform.c3 * v.z + transform.c4;
    points->SetPoint(i, x, y, z);
  }
  polydata->SetPoints(points);
}

// Normals go through the inverse transpose of the transform's linear part, so that a
// scaled node keeps its normals perpendicular to its surface.
void SetNormals(const aiMesh& mesh, const aiMatrix4x4& transform, vtkPolyData* polydata)
{
  if (!mesh.mNormals)
  {
    return;
  }
  aiMatrix3x3 normalMatrix(transform);
  normalMatrix.Inverse().Transpose();
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(mesh.mNumVertices);
  for (unsigned int i = 0; i < mesh.mNumVertices; ++i)
  {
    aiVector3D n = normalMatrix * mesh.mNormals[i];
    const float length = n.Length();
    if (length > 0.0f && std::isfinite(length))
    {
      n /= length;
    }
    const float tuple[3] = { n.x, n.y, n.z };
    normals->SetTypedTuple(i, tuple);
  }
  polydata->GetPointData()->SetNormals(normals);
}

void SetColors(const aiMesh& mesh, vtkPolyData* polydata)
{
  if (!mesh.mColors[0])
  {
    return;
  }
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(4);
  colors->SetNumberOfTuples(mesh.mNumVertices);
  for (unsigned int i = 0; i < mesh.mNumVertices; ++i)
  {
    const aiColor4D& c = mesh.mColors[0][i];
    const unsigned char rgba[4] = { ToByte(c.r), ToByte(c.g), ToByte(c.b), ToByte(c.a) };
    colors->SetTypedTuple(i, rgba);
  }
  polydata->GetPointData()->SetScalars(colors);
}

void SetTextureCoordinates(const aiMesh& mesh, vtkPolyData* polydata)
{
  if (!mesh.mTextureCoords[0])
  {
    return;
  }
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(mesh.mNumVertices);
  for (unsigned int i = 0; i < mesh.mNumVertices; ++i)
  {
    const float uv[2] = { mesh.mTextureCoords[0][i].x, mesh.mTextureCoords[0][i].y };
    tcoords->SetTypedTuple(i, uv);
  }
  polydata->GetPointData()->SetTCoords(tcoords);
}

// Faces by their size: 1 index a vertex, 2 a line, more a polygon. Indices are checked
// again here although ValidateDataStructure did: a bad one would crash VTK later.
void SetCells(const aiMesh& mesh, vtkPolyData* polydata)
{
  vtkNew<vtkCellArray> verts, lines, polys;
  std::vector<vtkIdType> ids;
  // A scene read without validation may count faces it does not hold.
  for (unsigned int f = 0; mesh.mFaces && f < mesh.mNumFaces; ++f)
  {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices == 0 || !face.mIndices)
    {
      continue;
    }
    ids.assign(face.mIndices, face.mIndices + face.mNumIndices);
    if (std::any_of(ids.begin(), ids.end(),
          [&mesh](vtkIdType id) { return id < 0 || id >= vtkIdType(mesh.mNumVertices); }))
    {
      continue;
    }
    vtkCellArray* cells = face.mNumIndices == 1 ? verts : (face.mNumIndices == 2 ? lines : polys);
    cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  polydata->SetVerts(verts);
  polydata->SetLines(lines);
  polydata->SetPolys(polys);
}

void AddTuple(vtkFieldData* fields, const char* name, const double* values, int components)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->InsertNextTuple(values);
  fields->AddArray(array);
}

void AddString(vtkFieldData* fields, const char* name, const std::string& value)
{
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fields->AddArray(array);
}

// One colour of the material, when the file gives it.
void AddColor(vtkFieldData* fields, const aiMaterial& material, const char* key,
  unsigned int type, unsigned int index, const char* name)
{
  aiColor3D color;
  if (material.Get(key, type, index, color) == AI_SUCCESS)
  {
    const double rgb[3] = { color.r, color.g, color.b };
    AddTuple(fields, name, rgb, 3);
  }
}

void AddScalar(vtkFieldData* fields, const aiMaterial& material, const char* key,
  unsigned int type, unsigned int index, const char* name)
{
  float value = 0.0f;
  if (material.Get(key, type, index, value) == AI_SUCCESS)
  {
    const double number = value;
    AddTuple(fields, name, &number, 1);
  }
}

// The diffuse texture's path, absolute; embedded textures ("*0") are not carried.
void AddDiffuseTexture(vtkFieldData* fields, const aiMaterial& material, const std::string& dir)
{
  aiString path;
  if (material.GetTextureCount(aiTextureType_DIFFUSE) == 0 ||
    material.GetTexture(aiTextureType_DIFFUSE, 0, &path) != AI_SUCCESS)
  {
    return;
  }
  std::string texture = NameOf(path);
  if (texture.empty() || texture[0] == '*')
  {
    return;
  }
  std::replace(texture.begin(), texture.end(), '\\', '/');
  AddString(fields, "MaterialDiffuseTexture", texture[0] == '/' ? texture : dir + "/" + texture);
}

void SetMaterial(const aiScene& scene, const aiMesh& mesh, const std::string& directory,
  vtkPolyData* polydata)
{
  if (mesh.mMaterialIndex >= scene.mNumMaterials || !scene.mMaterials[mesh.mMaterialIndex])
  {
    return;
  }
  const aiMaterial& material = *scene.mMaterials[mesh.mMaterialIndex];
  vtkFieldData* fields = polydata->GetFieldData();
  aiString name;
  if (material.Get(AI_MATKEY_NAME, name) == AI_SUCCESS)
  {
    AddString(fields, "MaterialName", NameOf(name));
  }
  AddColor(fields, material, AI_MATKEY_COLOR_AMBIENT, "MaterialAmbient");
  AddColor(fields, material, AI_MATKEY_COLOR_DIFFUSE, "MaterialDiffuse");
  AddColor(fields, material, AI_MATKEY_COLOR_SPECULAR, "MaterialSpecular");
  AddColor(fields, material, AI_MATKEY_COLOR_EMISSIVE, "MaterialEmission");
  AddScalar(fields, material, AI_MATKEY_SHININESS, "MaterialShininess");
  AddScalar(fields, material, AI_MATKEY_OPACITY, "MaterialOpacity");
  AddDiffuseTexture(fields, material, directory);
}

vtkSmartPointer<vtkPolyData> MakeBlock(const aiScene& scene, const aiMesh& mesh,
  const aiMatrix4x4& transform, const std::string& directory)
{
  auto polydata = vtkSmartPointer<vtkPolyData>::New();
  SetPoints(mesh, transform, polydata);
  SetCells(mesh, polydata);
  SetNormals(mesh, transform, polydata);
  SetColors(mesh, polydata);
  SetTextureCoordinates(mesh, polydata);
  SetMaterial(scene, mesh, directory, polydata);
  return polydata;
}

struct Walk
{
  const aiScene& Scene;
  const std::string& Directory;
  vtkMultiBlockDataSet* Output;
  unsigned int Depth = 0;
  unsigned long long Visits = 0;
};

// A node graph with a cycle (refused by validation, but a scene read leniently is not
// validated) would be walked forever; a real scene has far fewer nodes than this.
const unsigned long long MaximumVisits = 1000000;

// Depth-first over the node tree, the transforms accumulated from the root. The depth is
// bounded: a corrupt file could make the tree arbitrarily deep and the stack overflow.
void AppendNode(Walk& walk, const aiNode& node, const aiMatrix4x4& parent)
{
  if (++walk.Visits > MaximumVisits)
  {
    return;
  }
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned int m = 0; m < node.mNumMeshes && node.mMeshes; ++m)
  {
    const unsigned int index = node.mMeshes[m];
    if (index >= walk.Scene.mNumMeshes || !walk.Scene.mMeshes[index])
    {
      continue;
    }
    const aiMesh& mesh = *walk.Scene.mMeshes[index];
    if (!mesh.mVertices || mesh.mNumVertices == 0)
    {
      continue;
    }
    const unsigned int block = walk.Output->GetNumberOfBlocks();
    walk.Output->SetBlock(block, MakeBlock(walk.Scene, mesh, transform, walk.Directory));
    walk.Output->GetMetaData(block)->Set(
      vtkCompositeDataSet::NAME(), (NameOf(node.mName) + "/" + NameOf(mesh.mName)).c_str());
  }
  if (++walk.Depth < 1024)
  {
    for (unsigned int c = 0; c < node.mNumChildren && node.mChildren; ++c)
    {
      if (node.mChildren[c])
      {
        AppendNode(walk, *node.mChildren[c], transform);
      }
    }
  }
  --walk.Depth;
}
}

//------------------------------------------------------------------------------
unsigned int vtkPhongAssimpScene::AppendBlocks(
  const aiScene& scene, const std::string& directory, vtkMultiBlockDataSet* output)
{
  const unsigned int before = output->GetNumberOfBlocks();
  if (scene.mRootNode)
  {
    Walk walk{ scene, directory, output };
    AppendNode(walk, *scene.mRootNode, aiMatrix4x4());
  }
  // Meshes no node uses would be lost; a scene made only of them is drawn untransformed.
  const bool unused = output->GetNumberOfBlocks() == before;
  for (unsigned int m = 0; unused && scene.mMeshes && m < scene.mNumMeshes; ++m)
  {
    if (scene.mMeshes[m] && scene.mMeshes[m]->mVertices && scene.mMeshes[m]->mNumVertices)
    {
      const unsigned int block = output->GetNumberOfBlocks();
      output->SetBlock(block, MakeBlock(scene, *scene.mMeshes[m], aiMatrix4x4(), directory));
      output->GetMetaData(block)->Set(vtkCompositeDataSet::NAME(), NameOf(scene.mMeshes[m]->mName).c_str());
    }
  }
  return output->GetNumberOfBlocks() - before;
}
