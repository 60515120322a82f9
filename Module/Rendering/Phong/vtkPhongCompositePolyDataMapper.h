/**
 * @class   vtkPhongCompositePolyDataMapper
 * @brief   vtkPhong's lighting for composite datasets (multiblock, partitioned), as ParaView draws
 * them
 *
 * vtkPhongCompositePolyDataMapper is VTK's composite mapper whose helpers (the polydata
 * mappers that draw the blocks, grouped by what arrays they carry) light with the same
 * generated shaders as vtkPhongPolyDataMapper: both are made from vtkPhongLightingMapper, so
 * there is one implementation with two entry points, and the same settings
 * (vtkPhongLightingSettings) under the same names. Which composite mapper depends on the VTK
 * version: before VTK 9.3 it is a vtkCompositePolyDataMapper2 (the helpers are
 * vtkCompositeMapperHelper2); from VTK 9.3 on, where that class is deprecated and ParaView draws
 * with vtkCompositePolyDataMapper, it is a vtkCompositePolyDataMapper whose delegators' batched
 * mappers are the helpers (docs/compatibility.md). Per-block colours, opacities and visibilities of
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

#include "vtkPhongLightingSettings.h" // for the settings
#include "vtkRenderingPhongModule.h"  // for export macro
#include "vtkVersionMacros.h"         // for VTK_VERSION_NUMBER

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

  /**
   * The lighting settings (vtkPhongLightingSettings, where each is documented), each settable
   * here under its own name, exactly as on vtkPhongPolyDataMapper: the debug view, light
   * culling, the visibility work (closed-surface culling and the depth pre-pass, for each
   * block mapper's blocks together), the shader cache and the two measurement-only switches.
   * LightingSettings: the settings object itself, which mappers may share.
   */
  vtkPhongLightingSettingsForwardingMacro();

  /**
   * The most the last planned primitives' approximations (light culling, per-vertex
   * lighting under ErrorBudget) may make a colour stray from the exact model, in 8-bit
   * levels: the largest over the blocks.
   */
  double GetErrorBound();

  ///@{
  /**
   * What else the blocks' last planned primitives spent ErrorBudget on, as
   * vtkPhongPolyDataMapper reports it for itself: the most approximate of their modes
   * (BudgetModes; "per fragment", "specular per vertex" or "per vertex"), and the largest
   * whole shininess a block raised by squaring (0: pow everywhere).
   */
  int GetBudgetMode();
  const char* GetBudgetModeAsString();
  int GetSquaredShininess();
  ///@}

  ///@{
  /**
   * Whether a block mapper culled back faces, and whether one drew with the depth pre-pass,
   * in the last render.
   */
  bool GetUsedClosedSurfaceCulling();
  bool GetUsedDepthPrePass();
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

  /**
   * Copy the lighting settings of another vtkPhongCompositePolyDataMapper, then what VTK's
   * composite mapper copies.
   */
  void ShallowCopy(vtkAbstractMapper* mapper) override;

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

private:
  vtkPhongCompositePolyDataMapper(const vtkPhongCompositePolyDataMapper&) = delete;
  void operator=(const vtkPhongCompositePolyDataMapper&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#undef VTKPHONG_COMPOSITE_SUPERCLASS

#endif
