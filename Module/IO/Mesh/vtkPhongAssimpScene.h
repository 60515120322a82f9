// vtkPhongAssimpReader's conversion of an assimp scene into VTK blocks: private to the
// module (not installed, not wrapped), so that no assimp type reaches a public header.

#ifndef vtkPhongAssimpScene_h
#define vtkPhongAssimpScene_h

#include <string>

struct aiScene;
class vtkMultiBlockDataSet;

namespace vtkPhongAssimpScene
{
/**
 * Appends to output one vtkPolyData block per mesh instance of the scene (each node's
 * meshes, the node's accumulated transform applied), named "<node>/<mesh>", with the
 * mesh's colours, normals and texture coordinates as point data and its material as field
 * data. Texture paths are made absolute from directory (the file's). Returns the number of
 * blocks appended.
 */
unsigned int AppendBlocks(
  const aiScene& scene, const std::string& directory, vtkMultiBlockDataSet* output);
}

#endif
