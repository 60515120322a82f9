#include "vtkPhongAssimpReader.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPhongAssimpScene.h"
#include "vtkPhongGltfCheck.h"

#include <vtksys/SystemTools.hxx>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/version.h>

#include <exception>
#include <sstream>

vtkStandardNewMacro(vtkPhongAssimpReader);

namespace
{
// What assimp does to the scene after reading it. ValidateDataStructure refuses indices
// out of range and similar corruption; FindInvalidData drops NaN or zero normals and
// texture coordinates. Normals are not generated: the mapper computes them (vtkOpenMeshNormals)
// with its own weighting and feature angle. Triangulate leaves points and lines as they are.
unsigned int PostProcessing(bool triangulate, bool join)
{
  unsigned int flags = aiProcess_ValidateDataStructure | aiProcess_FindInvalidData;
  flags |= triangulate ? aiProcess_Triangulate : 0u;
  flags |= join ? aiProcess_JoinIdenticalVertices : 0u;
  return flags;
}

// assimp keeps a point cloud (PLY or OBJ vertices without faces) as a mesh with no faces,
// which ValidateDataStructure refuses; one point face per vertex makes it a valid mesh of
// points. The scene is the importer's own, still to be post-processed.
void GivePointCloudsFaces(aiScene& scene)
{
  for (unsigned int m = 0; scene.mMeshes && m < scene.mNumMeshes; ++m)
  {
    aiMesh* mesh = scene.mMeshes[m];
    if (!mesh || mesh->mNumFaces != 0 || mesh->mFaces || !mesh->mVertices)
    {
      continue;
    }
    mesh->mFaces = new aiFace[mesh->mNumVertices];
    mesh->mNumFaces = mesh->mNumVertices;
    for (unsigned int v = 0; v < mesh->mNumVertices; ++v)
    {
      mesh->mFaces[v].mNumIndices = 1;
      mesh->mFaces[v].mIndices = new unsigned int[1]{ v };
    }
    mesh->mPrimitiveTypes = aiPrimitiveType_POINT;
  }
}

// The importer's scene for the file, post-processed; nullptr when assimp cannot read it.
// A scene only assimp's validation refuses (a light without a node, an empty mesh among
// good ones: files assimp's own viewer shows) is read again without post-processing:
// AppendBlocks checks what it uses itself. lenient tells the caller.
const aiScene* ImportScene(
  Assimp::Importer& importer, const std::string& path, unsigned int flags, bool& lenient)
{
  lenient = false;
  const aiScene* scene = importer.ReadFile(path, 0);
  if (scene)
  {
    GivePointCloudsFaces(*const_cast<aiScene*>(scene));
    scene = importer.ApplyPostProcessing(flags);
  }
  const std::string why = importer.GetErrorString();
  if (!scene && why.rfind("Validation failed", 0) == 0)
  {
    scene = importer.ReadFile(path, 0);
    lenient = scene != nullptr;
  }
  return scene;
}

// Reads the file into output; returns why it failed, or an empty string. The file is read
// with no post-processing first, so that point clouds can be completed before validation.
std::string ReadScene(
  const std::string& path, unsigned int flags, vtkMultiBlockDataSet* output, std::string& warning)
{
  Assimp::Importer importer;
  // STL's normals are per facet: they keep every vertex apart (JoinIdenticalVertices joins
  // only vertices equal in every attribute), so the surface could only ever look faceted.
  // Without them the vertices are shared and the mapper computes normals split at sharp
  // edges (its feature angle), as VTK's STL reader and vtkOpenMeshNormals do.
  if (vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path)) == ".stl")
  {
    importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS);
    flags |= aiProcess_RemoveComponent;
  }
  bool lenient = false;
  const aiScene* scene = ImportScene(importer, path, flags, lenient);
  if (!scene)
  {
    const std::string why = importer.GetErrorString();
    return why.empty() ? "assimp cannot read it." : why;
  }
  if (lenient)
  {
    warning = "assimp's validation refused the scene; it is read without post-processing.";
    // Deliberately leaked: assimp's destructor is not safe on a scene its validation
    // refused (a double free on its own OpenGEX/camera.ogex). Only such files leak.
    importer.GetOrphanedScene();
  }
  // An incomplete scene (assimp's flag for files of cameras, lights or animations) is
  // still drawn when it has meshes.
  if (scene->mNumMeshes == 0)
  {
    return "it holds no mesh.";
  }
  const std::string directory =
    vtksys::SystemTools::GetFilenamePath(vtksys::SystemTools::CollapseFullPath(path));
  if (vtkPhongAssimpScene::AppendBlocks(*scene, directory, output) == 0)
  {
    return "it holds no mesh.";
  }
  return std::string();
}
}

//------------------------------------------------------------------------------
vtkPhongAssimpReader::vtkPhongAssimpReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkPhongAssimpReader::~vtkPhongAssimpReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
bool vtkPhongAssimpReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return false;
  }
  const std::string extension = vtksys::SystemTools::GetFilenameLastExtension(fileName);
  Assimp::Importer importer;
  return !extension.empty() && importer.IsExtensionSupported(extension);
}

//------------------------------------------------------------------------------
std::string vtkPhongAssimpReader::GetSupportedExtensions()
{
  Assimp::Importer importer;
  std::string list;
  importer.GetExtensionList(list);
  return vtksys::SystemTools::LowerCase(list);
}

//------------------------------------------------------------------------------
std::string vtkPhongAssimpReader::GetAssimpVersion()
{
  std::ostringstream version;
  version << aiGetVersionMajor() << "." << aiGetVersionMinor() << "." << aiGetVersionPatch();
  return version.str();
}

//------------------------------------------------------------------------------
std::string vtkPhongAssimpReader::CheckFile() const
{
  if (!this->FileName || !*this->FileName)
  {
    return "No FileName was set.";
  }
  if (!vtksys::SystemTools::FileExists(this->FileName, true))
  {
    return std::string("Cannot open ") + this->FileName + ": no such file.";
  }
  const vtkTypeInt64 size =
    static_cast<vtkTypeInt64>(vtksys::SystemTools::FileLength(this->FileName));
  if (this->MaxFileSize > 0 && size > this->MaxFileSize)
  {
    return std::string(this->FileName) + " has " + std::to_string(size) +
      " bytes, more than MaxFileSize (" + std::to_string(this->MaxFileSize) + ").";
  }
  const std::string why = vtkPhongGltfCheck::WhyRefused(this->FileName);
  return why.empty() ? why : "Cannot read " + std::string(this->FileName) + ": " + why;
}

//------------------------------------------------------------------------------
int vtkPhongAssimpReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outputVector);
  std::string why = this->CheckFile();
  if (!why.empty())
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  vtkNew<vtkMultiBlockDataSet> blocks;
  std::string warning;
  try
  {
    why = ReadScene(this->FileName, PostProcessing(this->Triangulate, this->JoinIdenticalVertices),
      blocks, warning);
  }
  catch (const std::exception& error)
  {
    why = std::string("assimp failed: ") + error.what();
  }
  if (!why.empty())
  {
    vtkErrorMacro(<< "Cannot read " << this->FileName << ": " << why);
    return 0;
  }
  if (!warning.empty())
  {
    vtkWarningMacro(<< this->FileName << ": " << warning);
  }
  output->ShallowCopy(blocks);
  return 1;
}

//------------------------------------------------------------------------------
void vtkPhongAssimpReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "MaxFileSize: " << this->MaxFileSize << "\n";
  os << indent << "Triangulate: " << this->Triangulate << "\n";
  os << indent << "JoinIdenticalVertices: " << this->JoinIdenticalVertices << "\n";
}
