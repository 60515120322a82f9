/**
 * @class   vtkPhongObjectFactory
 * @brief   the one switch that gives every VTK program vtkPhong's lighting
 *
 * VTK makes its mappers through the object factory: `vtkPolyDataMapper::New()` returns
 * the OpenGL2 module's `vtkOpenGLPolyDataMapper` because that module registers a factory.
 * SetOverridesEnabled(true) registers this factory, whose overrides return
 * vtkPhongPolyDataMapper for `vtkPolyDataMapper` and `vtkOpenGLPolyDataMapper`, and
 * vtkPhongCompositePolyDataMapper for VTK's composite mapper (`vtkCompositePolyDataMapper2`
 * before VTK 9.3, `vtkCompositePolyDataMapper` from 9.3 on: the class it derives from), so
 * code that never names vtkPhong (a PyVista or vedo script, a VTK example) lights with it.
 * Python: `import vtkphong.overrides`. `vtkPolyDataMapper::New()` asks the factory; the
 * concrete OpenGL classes' own New() does not (VTK makes them with `new`), so the overrides
 * of `vtkOpenGLPolyDataMapper` and of the composite mappers answer code that asks the
 * factory by name (vtkObjectFactory::CreateInstance).
 *
 * Composite data made by VTK's own composite mapper: from VTK 9.3 on,
 * `vtkCompositePolyDataMapper::New()` does not ask the factory, but every composite mapper
 * makes its delegators through `vtkCompositePolyDataMapperDelegator::New()`, which does; its
 * override gives VTK's own composite mapper (PyVista's `add_composite`, ParaView's Surface
 * representation) vtkPhong's block mappers. On VTK 9.1,
 * `vtkCompositePolyDataMapper2::New()` and its helpers' New() never ask the factory: a
 * composite mapper made by its class name (`vtkCompositePolyDataMapper2()` in Python) stays
 * VTK's there (docs/compatibility.md); vtkPhongCompositePolyDataMapper, or "Phong Surface"
 * in ParaView, is the way.
 *
 * Who wins: the factory asks the registered factories in registration order and takes the
 * first answer. When the switch is turned on, the same overrides are disabled in the
 * factories registered before (VTK's OpenGL2 one), and factories registered later come
 * after this one: vtkPhong wins whatever the import order. Turning it off unregisters this
 * factory and enables the others' overrides of those classes again.
 *
 * Only objects made after the switch are affected; existing mappers keep their class.
 *
 * Settings: every mapper the factory makes, and every block mapper it gives VTK's composite
 * mapper, starts from vtkPhongLightingSettings::GetFactoryDefaults(), one object for the
 * process. A script that never names vtkPhong's mappers sets the lighting there before it
 * builds its scene: `vtkphong.overrides.defaults().SetErrorBudget(1.0)` in Python, and
 * PyVista's or vedo's scenes then spend that budget.
 *
 * @sa vtkPhongPolyDataMapper vtkPhongCompositePolyDataMapper
 */

#ifndef vtkPhongObjectFactory_h
#define vtkPhongObjectFactory_h

#include "vtkObjectFactory.h"
#include "vtkRenderingPhongModule.h" // for export macro

class VTKRENDERINGPHONG_EXPORT vtkPhongObjectFactory : public vtkObjectFactory
{
public:
  static vtkPhongObjectFactory* New();
  vtkTypeMacro(vtkPhongObjectFactory, vtkObjectFactory);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  const char* GetVTKSourceVersion() override;
  const char* GetDescription() override;

  ///@{
  /**
   * Switch the overrides on or off for the whole process. Default off.
   */
  static void SetOverridesEnabled(bool enabled);
  static bool GetOverridesEnabled();
  ///@}

  /**
   * Switch off (or on again) the overrides of the classes vtkPhong overrides in every factory
   * registered so far, so that a vtkPhong factory registered after them is asked first.
   * SetOverridesEnabled does this; the factory library that VTK_AUTOLOAD_PATH loads does it
   * before its factory is registered.
   */
  static void SetOtherFactoriesOverridesEnabled(bool enabled);

protected:
  vtkPhongObjectFactory();
  ~vtkPhongObjectFactory() override = default;

private:
  vtkPhongObjectFactory(const vtkPhongObjectFactory&) = delete;
  void operator=(const vtkPhongObjectFactory&) = delete;
};

#endif
