/**
 * @file    vtkPhongOpenGL.h
 * @brief   VTK's OpenGL loader, whichever the VTK version has (private)
 *
 * VTK 9.4 replaced GLEW by glad: `vtk_glew.h` (modules VTK::glew, VTK::opengl) became
 * `vtk_glad.h` (VTK::glad). The modules name all three as OPTIONAL_DEPENDS, and the files
 * that call OpenGL include this header, which takes whichever header exists.
 */

#ifndef vtkPhongOpenGL_h
#define vtkPhongOpenGL_h

#if __has_include("vtk_glad.h")
#include "vtk_glad.h" // IWYU pragma: export
#else
#include "vtk_glew.h" // IWYU pragma: export
#endif

#endif
// VTK-HeaderTest-Exclude: vtkPhongOpenGL.h
