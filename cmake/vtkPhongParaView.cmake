# Finds Debian's ParaView (paraview-dev) and, through it, its VTK: ParaView 5.11 with a
# bundled VTK 9.2 snapshot on Debian 12, ParaView 5.13 with a bundled VTK 9.3 on Debian 13,
# ParaView 6.1 on the system VTK (9.6) on Debian testing, where python3-paraview installs
# beside python3-vtk9 and neither trap below exists (VTKPHONG_PARAVIEW_PYTHON_ROOT is /).
#
# Two Debian traps of the bundled VTK are handled here:
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

# The version names paraview-dev's directories (CMake package, plugins); by default the one
# installed.
file(GLOB vtkphong_paraview_dirs LIST_DIRECTORIES true "/usr/lib/x86_64-linux-gnu/cmake/paraview-*")
set(vtkphong_paraview_version "5.11")
if (vtkphong_paraview_dirs)
  list(GET vtkphong_paraview_dirs 0 vtkphong_paraview_dir)
  string(REGEX REPLACE "^.*/paraview-" "" vtkphong_paraview_version "${vtkphong_paraview_dir}")
endif ()
set(VTKPHONG_PARAVIEW_VERSION "${vtkphong_paraview_version}"
  CACHE STRING "ParaView's major.minor version (5.11 on Debian 12, 5.13 on Debian 13, 6.1 on testing)")
set(VTKPHONG_PARAVIEW_CMAKE_DIR
  "/usr/lib/x86_64-linux-gnu/cmake/paraview-${VTKPHONG_PARAVIEW_VERSION}"
  CACHE PATH "paraview-dev's CMake package directory")
set(VTKPHONG_PARAVIEW_PYTHON_ROOT "${CMAKE_BINARY_DIR}/python3-paraview"
  CACHE PATH "Where python3-paraview's .deb is unpacked (dpkg-deb -x)")

# ParaView 5.13 adds the incubator's Python modules, also in python3-paraview.
foreach (targets_file IN ITEMS
    "${VTKPHONG_PARAVIEW_CMAKE_DIR}/vtk/VTKPython-targets.cmake"
    "${VTKPHONG_PARAVIEW_CMAKE_DIR}/ParaViewPython-targets.cmake"
    "${VTKPHONG_PARAVIEW_CMAKE_DIR}/ParaViewTools-targets.cmake"
    "${VTKPHONG_PARAVIEW_CMAKE_DIR}/ParaViewPythonIncubator-targets.cmake")
  if (NOT EXISTS "${targets_file}")
    # The incubator is 5.13's; ParaView on the system VTK has no vtk/ package of its own.
    if (targets_file MATCHES "Incubator|/vtk/")
      continue ()
    endif ()
    message(FATAL_ERROR "${targets_file} is missing: install paraview-dev.")
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
find_package(ParaView "${VTKPHONG_PARAVIEW_VERSION}" REQUIRED
  PATHS "${VTKPHONG_PARAVIEW_CMAKE_DIR}" NO_DEFAULT_PATH
  COMPONENTS
    RemotingViews
    VTKExtensionsFiltersRendering)
# ParaView 5.13's VTK::hdf5 and VTK::netcdf, linked through RemotingViews, name HDF5's and
# netCDF's own targets, which its VTK package finds only when those components are asked for.
if (TARGET VTK::hdf5 AND NOT TARGET hdf5::hdf5 AND IS_DIRECTORY "${VTKPHONG_PARAVIEW_CMAKE_DIR}/vtk")
  find_package(VTK REQUIRED
    PATHS "${VTKPHONG_PARAVIEW_CMAKE_DIR}/vtk" NO_DEFAULT_PATH
    COMPONENTS hdf5 netcdf)
endif ()
message(STATUS "vtkPhong: building against ParaView ${ParaView_VERSION} (VTK ${VTK_VERSION})")

set(hierarchy_root "${VTKPHONG_PARAVIEW_PYTHON_ROOT}/usr/lib/x86_64-linux-gnu/vtk/hierarchy")
string(REPLACE "//" "/" hierarchy_root "${hierarchy_root}")
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
