/**
 * @class   vtkPhongAssimpReader
 * @brief   reads the mesh formats of the Open Asset Import Library (assimp) into blocks
 *
 * vtkPhongAssimpReader reads every format assimp reads (OBJ with its MTL, PLY, STL, OFF,
 * glTF and GLB, FBX, COLLADA, 3DS, and some forty more; see GetSupportedExtensions) into a
 * vtkMultiBlockDataSet with one vtkPolyData block per mesh instance of the scene:
 *
 * - the node transforms of the scene are applied to the points and normals, so a mesh that
 *   several nodes use gives one block per node;
 * - each block is named "<node>/<mesh>" (vtkCompositeDataSet::NAME());
 * - faces of one index become verts (point clouds), of two lines, of three or more polygons
 *   (triangulated by assimp when Triangulate is on, so concave polygons draw right);
 * - per-vertex colours become unsigned-char RGBA point scalars "Colors" (assimp's float
 *   colours scaled by 255 and clamped), normals the point normals "Normals", the first set
 *   of texture coordinates the point tcoords "TCoords";
 * - the material of the mesh is carried as field data on the block: "MaterialName",
 *   "MaterialAmbient", "MaterialDiffuse", "MaterialSpecular", "MaterialEmission" (RGB),
 *   "MaterialShininess" (the file's exponent, unclamped), "MaterialOpacity" and
 *   "MaterialDiffuseTexture" (the texture's path made absolute; absent when the material
 *   has none or the texture is embedded). docs/io.md maps each onto vtkPhongProperty;
 *   vtkphong.materials.apply_material does it in Python.
 *
 * A file that cannot be read (missing, larger than MaxFileSize, refused by assimp's
 * validation, or holding no mesh) is reported with vtkErrorMacro and gives an empty output.
 * assimp's own exceptions (including std::bad_alloc) are caught and reported. assimp types
 * stay out of this header.
 *
 * @sa vtkPhongOFFReader
 */

#ifndef vtkPhongAssimpReader_h
#define vtkPhongAssimpReader_h

#include "vtkIOMeshModule.h" // for export macro
#include "vtkMultiBlockDataSetAlgorithm.h"

#include <string> // for std::string

class VTKIOMESH_EXPORT vtkPhongAssimpReader : public vtkMultiBlockDataSetAlgorithm
{
public:
  static vtkPhongAssimpReader* New();
  vtkTypeMacro(vtkPhongAssimpReader, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file to read. Default none.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Files larger than this many bytes are refused before assimp sees them: assimp reads a
   * whole file into memory and its scene takes several times more. Default 1 GiB; 0 means
   * no limit.
   */
  vtkSetClampMacro(MaxFileSize, vtkTypeInt64, 0, VTK_TYPE_INT64_MAX);
  vtkGetMacro(MaxFileSize, vtkTypeInt64);
  ///@}

  ///@{
  /**
   * Whether assimp splits polygons of more than three vertices into triangles (ear
   * clipping, right for concave polygons, where VTK's fan is not). Default on.
   */
  vtkSetMacro(Triangulate, bool);
  vtkGetMacro(Triangulate, bool);
  vtkBooleanMacro(Triangulate, bool);
  ///@}

  ///@{
  /**
   * Whether vertices equal in every attribute are merged, so that a smooth surface written
   * face by face (OBJ, STL) shares its vertices and gets smooth normals. Default on.
   */
  vtkSetMacro(JoinIdenticalVertices, bool);
  vtkGetMacro(JoinIdenticalVertices, bool);
  vtkBooleanMacro(JoinIdenticalVertices, bool);
  ///@}

  /**
   * Whether assimp has an importer for the file's extension (the content is not read).
   */
  static bool CanReadFile(const char* fileName);

  /**
   * The extensions assimp reads, as "*.3ds;*.obj;..." (lower case).
   */
  static std::string GetSupportedExtensions();

  /**
   * The version of the assimp library linked, as "5.2.5".
   */
  static std::string GetAssimpVersion();

protected:
  vtkPhongAssimpReader();
  ~vtkPhongAssimpReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // The reasons a file is refused before assimp reads it; empty when it may be read.
  std::string CheckFile() const;

  char* FileName = nullptr;
  vtkTypeInt64 MaxFileSize = vtkTypeInt64(1) << 30;
  bool Triangulate = true;
  bool JoinIdenticalVertices = true;

private:
  vtkPhongAssimpReader(const vtkPhongAssimpReader&) = delete;
  void operator=(const vtkPhongAssimpReader&) = delete;
};

#endif
