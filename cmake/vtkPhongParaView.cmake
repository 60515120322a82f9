# Finds Debian 12's ParaView 5.11 (paraview-dev) and, through it, the VTK 9.2 it bundles.
#
# Two Debian traps are handled here:
#
# - paraview-dev's CMake package imports targets whose files only python3-paraview ships
#   (VTK's and ParaView's Python modules, pvpython). python3-paraview conflicts with
#   python3-vtk9, which the rest of the project needs, so it is not installed: those
#   targets get INTERFACE stand-ins before find_package, and CMake's check of their files
#   is skipped. Nothing here links them.
# - The plugin's client-server wrapping reads the wrapping hierarchy files of ParaView's
#   modules, also shipped only by python3-paraview. VTKPHONG_PARAVIEW_PYTHON_ROOT names a
#   directory where python3-paraview's .deb is unpacked (vtkphong.sh paraview does it:
#   apt-get download + dpkg-deb -x); the module targets are pointed at its hierarchy files.
#   pvbatch finds ParaView's Python package there too (PYTHONPATH, see ParaView/).

set(VTKPHONG_PARAVIEW_CMAKE_DIR "/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11"
  CACHE PATH "paraview-dev's CMake package directory")
set(VTKPHONG_PARAVIEW_PYTHON_ROOT "${CMAKE_BINARY_DIR}/python3-paraview"
  CACHE PATH "Where python3-paraview's .deb is unpacked (dpkg-deb -x)")

foreach (targets_file IN ITEMS
    "${VTKPHONG_PARAVIEW_CMAKE_DIR}/vtk/VTKPython-targets.cmake"
    "${VTKPHONG_PARAVIEW_CMAKE_DIR}/ParaViewPython-targets.cmake"
    "${VTKPHONG_PARAVIEW_CMAKE_DIR}/ParaViewTools-targets.cmake")
  if (NOT EXISTS "${targets_file}")
    message(FATAL_ERROR "${targets_file} is missing: install paraview-dev (Debian 12).")
  endif ()
  file(STRINGS "${targets_file}" expected REGEX "^foreach\\(_cmake_expected_target IN ITEMS ")
  string(REGEX REPLACE "^foreach\\(_cmake_expected_target IN ITEMS (.*)\\)$" "\\1"
    expected "${expected}")
  separate_arguments(expected)
  foreach (target IN LISTS expected)
    if (NOT TARGET "${target}")
      add_library("${target}" INTERFACE IMPORTED)
    endif ()
  endforeach ()
endforeach ()

# ParaView's VTK::Python target links Python3::Module without finding it.
find_package(Python3 REQUIRED COMPONENTS Interpreter Development.Module)
find_package(ParaView 5.11 REQUIRED
  PATHS "${VTKPHONG_PARAVIEW_CMAKE_DIR}" NO_DEFAULT_PATH
  COMPONENTS
    RemotingViews
    VTKExtensionsFiltersRendering)
message(STATUS "vtkPhong: building against ParaView ${ParaView_VERSION} (VTK ${VTK_VERSION})")

set(hierarchy_root "${VTKPHONG_PARAVIEW_PYTHON_ROOT}/usr/lib/x86_64-linux-gnu/vtk/hierarchy")
if (NOT IS_DIRECTORY "${hierarchy_root}")
  message(FATAL_ERROR
    "No ParaView wrapping hierarchy under ${VTKPHONG_PARAVIEW_PYTHON_ROOT}: unpack "
    "python3-paraview there (apt-get download python3-paraview && dpkg-deb -x "
    "python3-paraview_*.deb ${VTKPHONG_PARAVIEW_PYTHON_ROOT}), or run ./vtkphong.sh paraview.")
endif ()
get_property(imported_targets DIRECTORY PROPERTY IMPORTED_TARGETS)
foreach (target IN LISTS imported_targets)
  get_target_property(hierarchy "${target}" "INTERFACE_vtk_module_hierarchy")
  if (hierarchy)
    string(REGEX REPLACE "^.*/vtk/hierarchy" "${hierarchy_root}" hierarchy "${hierarchy}")
    set_property(TARGET "${target}" PROPERTY "INTERFACE_vtk_module_hierarchy" "${hierarchy}")
  endif ()
endforeach ()
