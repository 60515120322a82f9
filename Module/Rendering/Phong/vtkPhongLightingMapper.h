/**
 * @class   vtkPhongLightingMapper
 * @brief   VTK's OpenGL polydata mapper `Base`, lit by vtkPhong: every lighting override, once
 *
 * vtkPhongLightingMapper<Base> is the one implementation of what vtkPhong adds to a VTK
 * OpenGL polydata mapper: it reads the mapper's protected state for each primitive and has
 * vtkPhongMapperCore plan, build and feed the lighting shader (GetNeedToRebuildShaders,
 * UpdateShaders, BuildShaders, ReplaceShaderLight, the Set*ShaderParameters), reports
 * problems after each draw, and draws with the visibility work (closed-surface culling,
 * the depth pre-pass and its visible clusters).
 *
 * Two classes are made from it: vtkPhongPolyDataMapper (Base = vtkOpenGLPolyDataMapper,
 * one polydata) and the composite mapper's block mapper (vtkPhongBlockMapper, Base = the
 * VTK class that draws a group of blocks from one vertex buffer: vtkCompositeMapperHelper2
 * before VTK 9.3, vtkOpenGLBatchedPolyDataMapper from 9.3 on). What differs between them is
 * what the buffer holds and whose settings apply, and each answers that through the
 * protected virtual functions below; nothing else is written twice.
 *
 * The implementation is in vtkPhongLightingMapper.txx, instantiated inside the rendering
 * module for exactly those bases.
 *
 * @sa vtkPhongPolyDataMapper vtkPhongCompositePolyDataMapper vtkPhongMapperCore
 */

#ifndef vtkPhongLightingMapper_h
#define vtkPhongLightingMapper_h

#include "vtkPhongLightingSettings.h" // for the settings
#include "vtkRenderingPhongModule.h"  // for export macro
#include "vtkShader.h"                // for vtkShader::Type
#include "vtkType.h"                  // for vtkIdType

#include <map>    // for std::map
#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

class vtkActor;
class vtkOpenGLHelper;
class vtkPhongMapperCore;
class vtkPolyData;
class vtkRenderer;
class vtkShaderProperty;
class vtkWindow;
struct vtkPhongBufferBlock;

template <class Base>
class VTKRENDERINGPHONG_EXPORT vtkPhongLightingMapper : public Base
{
public:
  vtkTemplateTypeMacro(vtkPhongLightingMapper, Base);

  void ReleaseGraphicsResources(vtkWindow* window) override;

  /**
   * The lighting core (plans, variants, statistics).
   */
  vtkPhongMapperCore* GetCore();

  ///@{
  /**
   * What the last draw did: whether it culled the back faces of closed surfaces, whether it
   * drew with the depth pre-pass, the triangles its depth pass drew (0 without one), and the
   * depth complexity last measured by the automatic pre-pass (0: not measured).
   */
  bool GetUsedClosedSurfaceCulling() const;
  bool GetUsedDepthPrePass() const;
  double GetDepthPassTriangles() const;
  double GetDepthComplexity() const;
  ///@}

protected:
  vtkPhongLightingMapper();
  ~vtkPhongLightingMapper() override;

  ///@{
  /**
   * What the two kinds of mapper answer differently.
   *
   * LightingSettings: the settings that apply (the mapper's own, or the composite mapper's).
   * LitBlocks: the polydata whose normals the vertex buffer holds. BlocksInBuffer: whether
   * every block in the vertex buffer is drawn in this pass, visible and opaque, with `blocks`
   * the blocks and where their points start (cleared when the buffer does not hold what they
   * say). VisibilityWorkAllowed: false where the colours forbid culling and the pre-pass.
   * ClippingPlanesSeen, HasSelection: what may open a closed surface. SurfaceBounds: the
   * model bounds the camera must see from outside. Reporter: the object errors name (the
   * mapper the user made). StockNeedToRebuildShaders: VTK's test. MaterialPerBlock: whether
   * VTK sets its material uniforms (colours, opacity) again for each block it draws.
   */
  virtual vtkPhongLightingSettings* LightingSettings() = 0;
  virtual std::vector<vtkPolyData*> LitBlocks() = 0;
  virtual bool BlocksInBuffer(std::vector<vtkPhongBufferBlock>& blocks) = 0;
  virtual bool VisibilityWorkAllowed() { return true; }
  virtual int ClippingPlanesSeen() { return this->GetNumberOfClippingPlanes(); }
  virtual bool HasSelection() { return false; }
  virtual void SurfaceBounds(double bounds[6]) = 0;
  virtual vtkObject* Reporter() { return this; }
  virtual bool StockNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act);
  virtual bool MaterialPerBlock() { return false; }
  ///@}

  /**
   * VTK's, then frees the copies VTK keeps of what it packed for upload
   * (vtkPhongBufferBlocks::ReleasePackedCopies).
   */
  void BuildBufferObjects(vtkRenderer* ren, vtkActor* act) override;

  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void UpdateShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void BuildShaders(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderLight(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetLightingShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void SetPropertyShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;

  /**
   * The mapper's own shader replacements (VTK before 9.2), or nullptr.
   */
  vtkShaderProperty* LegacyShaders() const;

private:
  unsigned int HiddenFaces(
    vtkRenderer* ren, vtkActor* act, const std::vector<vtkPhongBufferBlock>& blocks);
  void DrawSurfaces(vtkRenderer* ren, vtkActor* act, const std::vector<vtkPhongBufferBlock>& blocks,
    bool everyBlock, bool allowed);
  void DrawDepthPass(vtkRenderer* ren, vtkActor* act,
    const std::vector<vtkPhongBufferBlock>& blocks, bool culling, double triangles);

  vtkPhongLightingMapper(const vtkPhongLightingMapper&) = delete;
  void operator=(const vtkPhongLightingMapper&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongLightingMapper.h
