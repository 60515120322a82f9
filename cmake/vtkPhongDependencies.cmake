# Third-party libraries beside VTK, all from Debian 12's packages:
#   libopenmesh-dev (OpenMesh 9.0), libglm-dev, libopenimageio-dev, libassimp-dev
#   (assimp 5.2 on Debian 12, 5.4 on Debian 13).

find_package(OpenMesh REQUIRED)
if (NOT TARGET OpenMeshCore)
  message(FATAL_ERROR "OpenMesh was found but provides no OpenMeshCore target (install libopenmesh-dev).")
endif ()

find_package(glm REQUIRED)
if (TARGET glm::glm)
  set(VTKPHONG_GLM_TARGET glm::glm)
elseif (TARGET glm)
  set(VTKPHONG_GLM_TARGET glm)
else ()
  message(FATAL_ERROR "glm was found but provides no glm::glm target (install libglm-dev).")
endif ()

find_package(OpenImageIO REQUIRED)
# Debian's OpenImageIO target lists /usr/include/opencv4 as an include directory
# although libopenimageio-dev does not depend on OpenCV; CMake refuses a target
# whose include directory is missing, so drop that entry when it is absent.
if (TARGET OpenImageIO::OpenImageIO AND NOT EXISTS "/usr/include/opencv4")
  foreach (_vtkphong_property IN ITEMS INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
    get_target_property(_vtkphong_dirs OpenImageIO::OpenImageIO ${_vtkphong_property})
    if (_vtkphong_dirs)
      list(FILTER _vtkphong_dirs EXCLUDE REGEX "opencv4")
      set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${_vtkphong_property} "${_vtkphong_dirs}")
    endif ()
  endforeach ()
endif ()

# assimp, for vtkPhongAssimpReader (IO/Mesh, privately): its CMake package where it has
# one (Debian's has, target assimp::assimp), else pkg-config.
find_package(assimp QUIET)
if (NOT TARGET assimp::assimp)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(vtkphong_assimp REQUIRED IMPORTED_TARGET assimp)
  add_library(assimp::assimp INTERFACE IMPORTED)
  target_link_libraries(assimp::assimp INTERFACE PkgConfig::vtkphong_assimp)
endif ()
