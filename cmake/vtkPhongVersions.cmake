# What differs between the VTK versions vtkPhong builds against, on the CMake side, in one
# place (the C++ side is Module/Rendering/Phong/vtkPhongCompatibility.h, which tests the same
# version; docs/compatibility.md gives the reasons):
#
#   Debian 12: VTK 9.1; ParaView 5.11's VTK, a 9.2 snapshot of January 2023
#   Debian 13: VTK 9.3 (ParaView 5.13's too)
#
# VTKPHONG_VTK_9_3: VTK 9.3 or later. There
# - the composite mapper's helpers are made by a delegator (vtkCompositePolyDataMapper), so
#   the rendering module builds vtkPhongCompositeDelegator;
# - stock VTK clamps R.V at 1e-5 before pow() (VTK ef1cca17, September 2022), so its
#   shininess-0 lobe is 1 like vtkPhong's and that documented difference is gone;
# - wide lines and tubes whose segments are shorter than their width are drawn lengthened
#   (VTK 7c2be057, March 2022), which changes the picture of tubes made of short segments.
#
# VTKPHONG_VTK_CHANGES: the changes the tests expect, passed to the Python tests as the
# environment variable of the same name (comma-separated).
if (VTK_VERSION VERSION_GREATER_EQUAL "9.3")
  set(VTKPHONG_VTK_9_3 ON)
  set(VTKPHONG_VTK_CHANGES "stock-shininess-zero-lobe")
else ()
  set(VTKPHONG_VTK_9_3 OFF)
  set(VTKPHONG_VTK_CHANGES "")
endif ()
