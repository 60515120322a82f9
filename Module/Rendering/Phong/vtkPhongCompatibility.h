/**
 * @file    vtkPhongCompatibility.h
 * @brief   what differs between the VTK versions vtkPhong builds against, in one place
 *
 * vtkPhong builds against Debian 12's VTK 9.1, ParaView 5.11's VTK 9.2 and Debian 13's
 * VTK 9.3 (ParaView 5.13's VTK is 9.3 too). The C++ differences are here; the CMake side
 * (which files a version compiles) is in this directory's CMakeLists.txt, and the reasons
 * are in docs/compatibility.md. Private to the rendering module.
 */

#ifndef vtkPhongCompatibility_h
#define vtkPhongCompatibility_h

#include "vtkOpenGLHelper.h"
#include "vtkVersionMacros.h"

/**
 * VTK 9.3 and later. ParaView 5.11's VTK, a 9.2 snapshot of January 2023, is older than both
 * changes below (February and May 2023). The same test is in CMakeLists.txt and in
 * vtkPhongCompositePolyDataMapper.h (its superclass).
 *
 * - Composite data: vtkCompositePolyDataMapper hands each group of blocks to a
 *   vtkOpenGLBatchedPolyDataMapper made by a delegator (CreateADelegator);
 *   vtkCompositePolyDataMapper2 and its helpers (CreateHelper) are deprecated.
 * - A program that fails to build no longer replaces the mapper's (ForgetProgramBeforeBuild).
 */
#define VTKPHONG_VTK_9_3 (VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0))

/**
 * Before VTK 9.2 (VTK 9.1, Debian 12's): shader replacements may also be set on the mapper
 * (vtkOpenGLPolyDataMapper::AddShaderReplacement, kept in its LegacyShaderProperty); VTK
 * removed them in October 2021, before ParaView 5.11's snapshot.
 */
#define VTKPHONG_VTK_MAPPER_SHADER_REPLACEMENTS (VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 2, 0))

/**
 * VTK 9.7 and later (so VTKPHONG_VTK_9_3 too): factory overrides carry attributes
 * (vtkOverrideAttribute, the sixth argument of vtkObjectFactory::RegisterOverride), matched
 * against the user's preferences (vtkObjectFactory::SetPreferences, VTK_FACTORY_PREFER). The
 * feature is tested, not the version: the header is new in 9.7.0 (no 9.6 release has it). No
 * VTK that vtkPhong builds against here has it (docs/compatibility.md): the code under this
 * test is written to VTK 9.7.0's headers and is not compiled in this project's builds.
 */
#if __has_include("vtkOverrideAttribute.h")
#define VTKPHONG_HAS_OVERRIDE_ATTRIBUTES 1
#else
#define VTKPHONG_HAS_OVERRIDE_ATTRIBUTES 0
#endif

namespace vtkPhongCompatibility
{
/**
 * Called when a mapper is about to compile a new program for `cellBO`. Before VTK 9.3 the
 * mapper's UpdateShaders stores what the shader cache returns, nullptr when the program
 * fails to compile or link, and vtkPhongMapperCore::EndUpdateShaders sees the failure as a
 * null program. VTK 9.3 keeps the previous program instead (and reports "Could not set
 * shader program"), so the failure would go unseen and the previous variant drawn: the
 * program is forgotten first, which VTK 9.3 tolerates (it then skips the uniforms, and the
 * next rebuild starts from no program). The price: a rebuild that gets the same program from
 * the shader cache (VTK rebuilds when the property changes) binds the vertex attributes again,
 * which is cheap next to the rebuild itself. Before 9.3 a failed build with no previous
 * program would dereference it, so nothing is done there.
 */
inline void ForgetProgramBeforeBuild(vtkOpenGLHelper& cellBO)
{
#if VTKPHONG_VTK_9_3
  cellBO.Program = nullptr;
#else
  (void)cellBO;
#endif
}
}

#endif
