/**
 * @class   vtkPhongCompositePolyDataMapper
 * @brief   vtkPhong's lighting for composite datasets (multiblock, partitioned), as ParaView draws
 * them
 *
 * vtkPhongCompositePolyDataMapper is a vtkCompositePolyDataMapper2 whose helpers (the
 * polydata mappers that draw the blocks, grouped by what arrays they carry) light with the
 * same generated shaders as vtkPhongPolyDataMapper: the helpers forward their shader
 * overrides to the same vtkPhongMapperCore and vtkPhongShaderBuilder, so there is one
 * implementation with two entry points. Per-block colours, opacities and visibilities of
 * vtkCompositeDataDisplayAttributes keep working (the lighting then reads VTK's per-block
 * colour variables instead of ready-made material products).
 *
 * The material is the actor's vtkProperty or vtkPhongProperty, exactly as for
 * vtkPhongPolyDataMapper. Unlike that mapper, this one does not compute missing normals
 * itself: like stock VTK's composite mapper it draws the normals the blocks carry. Put
 * vtkOpenMeshNormals upstream (it runs on every block of a composite dataset) for smooth
 * shading of blocks without normals.
 *
 * @sa vtkPhongPolyDataMapper vtkCompositePolyDataMapper2 vtkOpenMeshNormals
 */

#ifndef vtkPhongCompositePolyDataMapper_h
#define vtkPhongCompositePolyDataMapper_h

#include "vtkCompositePolyDataMapper2.h"
#include "vtkPhongPolyDataMapper.h"  // for the DebugViews values
#include "vtkRenderingPhongModule.h" // for export macro

#include <string> // for std::string

class VTKRENDERINGPHONG_EXPORT vtkPhongCompositePolyDataMapper : public vtkCompositePolyDataMapper2
{
public:
  static vtkPhongCompositePolyDataMapper* New();
  vtkTypeMacro(vtkPhongCompositePolyDataMapper, vtkCompositePolyDataMapper2);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The debug view, as vtkPhongPolyDataMapper::SetDebugView. Default
   * vtkPhongPolyDataMapper::Final; one of vtkPhongPolyDataMapper::DebugViews (clamped).
   */
  vtkSetClampMacro(DebugView, int, vtkPhongPolyDataMapper::Final, vtkPhongPolyDataMapper::NormalVC);
  vtkGetMacro(DebugView, int);
  ///@}

  ///@{
  /**
   * The light shown by the SingleLight view: an index into the renderer's lights. Default 0;
   * range [0, VTK_INT_MAX] (an index past the last light shows black).
   */
  vtkSetClampMacro(DebugLightIndex, int, 0, VTK_INT_MAX);
  vtkGetMacro(DebugLightIndex, int);
  ///@}

  ///@{
  /**
   * Shader specialization, as vtkPhongPolyDataMapper::SetShaderSpecialization. Default on.
   */
  vtkSetMacro(ShaderSpecialization, bool);
  vtkGetMacro(ShaderSpecialization, bool);
  vtkBooleanMacro(ShaderSpecialization, bool);
  ///@}

  ///@{
  /**
   * Shader statistics summed over the helpers (one helper per kind of block: with or
   * without scalars, normals, texture coordinates), as vtkPhongPolyDataMapper reports them
   * for itself; and the lighting signature of the last variant a helper built (empty when
   * every primitive was drawn by VTK's code).
   */
  int GetShaderCompileCount();
  int GetNumberOfShaderVariants();
  const char* GetLastShaderSignature();
  ///@}

  /**
   * The number of helpers (polydata mappers) drawing the blocks now.
   */
  int GetNumberOfHelpers() { return static_cast<int>(this->Helpers.size()); }

protected:
  vtkPhongCompositePolyDataMapper();
  ~vtkPhongCompositePolyDataMapper() override;

  vtkCompositeMapperHelper2* CreateHelper() override;

  int DebugView = vtkPhongPolyDataMapper::Final;
  int DebugLightIndex = 0;
  bool ShaderSpecialization = true;

private:
  vtkPhongCompositePolyDataMapper(const vtkPhongCompositePolyDataMapper&) = delete;
  void operator=(const vtkPhongCompositePolyDataMapper&) = delete;

  std::string LastSignature;
};

#endif
