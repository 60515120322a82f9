/**
 * @class   vtkPhongCompositePolyDataMapper
 * @brief   vtkPhong's lighting for composite datasets (multiblock, partitioned), as ParaView draws
 * them
 *
 * vtkPhongCompositePolyDataMapper is VTK's composite mapper whose helpers (the polydata
 * mappers that draw the blocks, grouped by what arrays they carry) light with the same
 * generated shaders as vtkPhongPolyDataMapper: the helpers forward their shader overrides to
 * the same vtkPhongMapperCore and vtkPhongShaderBuilder, so there is one implementation with
 * two entry points. Which composite mapper depends on the VTK version: before VTK 9.3 it is a
 * vtkCompositePolyDataMapper2 (the helpers are vtkCompositeMapperHelper2); from VTK 9.3 on,
 * where that class is deprecated and ParaView draws with vtkCompositePolyDataMapper, it is a
 * vtkCompositePolyDataMapper whose delegators' batched mappers are the helpers
 * (docs/compatibility.md). Per-block colours, opacities and visibilities of
 * vtkCompositeDataDisplayAttributes keep working (the lighting then reads VTK's per-block
 * colour variables instead of ready-made material products).
 *
 * As vtkPhongPolyDataMapper, it culls the back faces of closed surfaces seen from outside
 * (SetClosedSurfaceCulling) and draws deep scenes with the automatic depth pre-pass
 * (SetDepthPrePass), over each helper's blocks together: culling (of back faces, of the
 * depth pass's hidden triangle clusters) only while all of them are visible and opaque.
 *
 * The material is the actor's vtkProperty or vtkPhongProperty, exactly as for
 * vtkPhongPolyDataMapper. Unlike that mapper, this one does not compute missing normals
 * itself: like stock VTK's composite mapper it draws the normals the blocks carry. Put
 * vtkOpenMeshNormals upstream (it runs on every block of a composite dataset) for smooth
 * shading of blocks without normals.
 *
 * @sa vtkPhongPolyDataMapper vtkCompositePolyDataMapper vtkCompositePolyDataMapper2
 * vtkOpenMeshNormals
 */

#ifndef vtkPhongCompositePolyDataMapper_h
#define vtkPhongCompositePolyDataMapper_h

#include "vtkPhongPolyDataMapper.h"  // for the DebugViews values
#include "vtkRenderingPhongModule.h" // for export macro
#include "vtkVersionMacros.h"        // for VTK_VERSION_NUMBER

#include <memory> // for std::unique_ptr

// The superclass by VTK version, as vtkPhongCompatibility.h (private) explains.
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
#include "vtkCompositePolyDataMapper.h" // for the superclass
#define VTKPHONG_COMPOSITE_SUPERCLASS vtkCompositePolyDataMapper
class vtkCompositePolyDataMapperDelegator;
#else
#include "vtkCompositePolyDataMapper2.h" // for the superclass
#define VTKPHONG_COMPOSITE_SUPERCLASS vtkCompositePolyDataMapper2
class vtkCompositeMapperHelper2;
#endif

class VTKRENDERINGPHONG_EXPORT vtkPhongCompositePolyDataMapper
  : public VTKPHONG_COMPOSITE_SUPERCLASS
{
public:
  static vtkPhongCompositePolyDataMapper* New();
  vtkTypeMacro(vtkPhongCompositePolyDataMapper, VTKPHONG_COMPOSITE_SUPERCLASS);
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
   * Interpolated dot products, as vtkPhongPolyDataMapper::SetInterpolatedDotProducts.
   * Default on.
   */
  vtkSetMacro(InterpolatedDotProducts, bool);
  vtkGetMacro(InterpolatedDotProducts, bool);
  vtkBooleanMacro(InterpolatedDotProducts, bool);
  ///@}

  ///@{
  /**
   * Light culling, as vtkPhongPolyDataMapper::SetLightCullingBound, over the whole actor's
   * bounds. Default 0.5 / 255; range [0, 1e9]; 0 evaluates every light.
   */
  vtkSetClampMacro(LightCullingBound, double, 0.0, 1.0e9);
  vtkGetMacro(LightCullingBound, double);
  ///@}

  ///@{
  /**
   * Culling of hidden back faces, as vtkPhongPolyDataMapper::SetClosedSurfaceCulling, for
   * each helper's blocks together (blocks with the same arrays share a helper): only while
   * every block of the helper is visible and opaque, so that no block left out opens a
   * surface the others close. Default on. UsedClosedSurfaceCulling: whether a helper culled
   * in the last render.
   */
  vtkSetMacro(ClosedSurfaceCulling, bool);
  vtkGetMacro(ClosedSurfaceCulling, bool);
  vtkBooleanMacro(ClosedSurfaceCulling, bool);
  bool GetUsedClosedSurfaceCulling();
  ///@}

  ///@{
  /**
   * Depth pre-pass, as vtkPhongPolyDataMapper::SetDepthPrePass, for each helper's blocks
   * together (without its occlusion culling of triangle clusters). Default
   * DepthPrePassAutomatic; one of vtkPhongPolyDataMapper::DepthPrePassModes (clamped).
   * Never for a helper whose blocks mix point and cell scalars, which VTK 9.1 colours wrongly.
   * UsedDepthPrePass: whether a helper drew with it in the last render.
   */
  vtkSetClampMacro(DepthPrePass, int, vtkPhongPolyDataMapper::DepthPrePassOff,
    vtkPhongPolyDataMapper::DepthPrePassAutomatic);
  vtkGetMacro(DepthPrePass, int);
  bool GetUsedDepthPrePass();
  ///@}

  ///@{
  /**
   * Occlusion culling of the depth pre-pass, as
   * vtkPhongPolyDataMapper::SetDepthPrePassOcclusionCulling, over each helper's blocks
   * together, while every one of them is visible and opaque. Default on.
   */
  vtkSetMacro(DepthPrePassOcclusionCulling, bool);
  vtkGetMacro(DepthPrePassOcclusionCulling, bool);
  vtkBooleanMacro(DepthPrePassOcclusionCulling, bool);
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
  int GetNumberOfHelpers();

#ifndef __VTK_WRAP__
  /**
   * What the block mappers draw for `block`: the block itself, or its copy with the cells
   * that name missing points collapsed (made once per modification of the block, reported
   * once). The bounds use the same copies.
   */
  vtkPolyData* GetValidBlock(vtkPolyData* block);
#endif

protected:
  vtkPhongCompositePolyDataMapper();
  ~vtkPhongCompositePolyDataMapper() override;

  ///@{
  /**
   * Make a helper that lights with vtkPhong (VTK 9.3: the delegator of a helper).
   */
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
  vtkCompositePolyDataMapperDelegator* CreateADelegator() override;
#else
  vtkCompositeMapperHelper2* CreateHelper() override;
#endif
  ///@}

  /**
   * The superclass's bounds, unless a leaf has cells naming missing points (which VTK's
   * bounds would read): then the visible leaves' bounds with those cells collapsed, and a
   * warning.
   */
  void ComputeBounds() override;

  int DebugView = vtkPhongPolyDataMapper::Final;
  int DebugLightIndex = 0;
  bool ShaderSpecialization = true;
  bool InterpolatedDotProducts = true;
  double LightCullingBound = 0.5 / 255.0;
  bool ClosedSurfaceCulling = true;
  int DepthPrePass = vtkPhongPolyDataMapper::DepthPrePassAutomatic;
  bool DepthPrePassOcclusionCulling = true;

private:
  vtkPhongCompositePolyDataMapper(const vtkPhongCompositePolyDataMapper&) = delete;
  void operator=(const vtkPhongCompositePolyDataMapper&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#undef VTKPHONG_COMPOSITE_SUPERCLASS

#endif
