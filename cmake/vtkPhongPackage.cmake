# The CMake package: find_package(vtkPhong) from an install prefix (or from the
# build tree) gives the vtkPhong::RenderingPhong target and vtkPhong_PYTHONPATH.

include(CMakePackageConfigHelpers)

set(VTKPHONG_VTK_PUBLIC_COMPONENTS
  "CommonCore CommonExecutionModel RenderingCore RenderingOpenGL2")
set(vtkphong_cmake_destination "${CMAKE_INSTALL_LIBDIR}/cmake/vtkPhong")

# Install tree: paths relative to the prefix.
set(VTKPHONG_PYTHONPATH_VAR "${VTKPHONG_PYTHON_DESTINATION}")
configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/vtkPhongConfig.cmake.in"
  "${CMAKE_BINARY_DIR}/CMakeFiles/vtkPhongConfig.cmake.install"
  INSTALL_DESTINATION "${vtkphong_cmake_destination}"
  PATH_VARS VTKPHONG_PYTHONPATH_VAR)

# Build tree: the same file, pointing into the build directory.
set(VTKPHONG_PYTHONPATH_VAR "${CMAKE_BINARY_DIR}/${VTKPHONG_PYTHON_DESTINATION}")
configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/vtkPhongConfig.cmake.in"
  "${CMAKE_BINARY_DIR}/${vtkphong_cmake_destination}/vtkPhongConfig.cmake"
  INSTALL_DESTINATION "${CMAKE_BINARY_DIR}/${vtkphong_cmake_destination}"
  PATH_VARS VTKPHONG_PYTHONPATH_VAR
  INSTALL_PREFIX "${CMAKE_BINARY_DIR}")

write_basic_package_version_file(
  "${CMAKE_BINARY_DIR}/${vtkphong_cmake_destination}/vtkPhongConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMinorVersion)

install(
  FILES       "${CMAKE_BINARY_DIR}/CMakeFiles/vtkPhongConfig.cmake.install"
  DESTINATION "${vtkphong_cmake_destination}"
  RENAME      "vtkPhongConfig.cmake")
install(
  FILES       "${CMAKE_BINARY_DIR}/${vtkphong_cmake_destination}/vtkPhongConfigVersion.cmake"
  DESTINATION "${vtkphong_cmake_destination}")
