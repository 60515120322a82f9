# What every module's Testing/ shares: the C++ helpers of Testing/Core (checks, scenes,
# one X connection per process) and the way Python tests run (VTK's Python with the build
# tree's vtkphong package). Included by the top-level CMakeLists.txt before the modules
# are built, since vtk_module_build() adds their tests.

set(VTKPHONG_TESTING_CORE_DIR "${CMAKE_CURRENT_LIST_DIR}")
set(VTKPHONG_TEST_OUTPUT_DIR "${CMAKE_BINARY_DIR}/Testing/Temporary")

# vtkphong_test_cxx_executable(<executable> <tests variable>)
#
# VTK's test driver for one module's tests (vtk_add_test_cxx made the list), built with the
# shared helpers. Tests include "vtkPhongTestUtilities.h" and friends from Testing/Core.
function (vtkphong_test_cxx_executable executable tests_variable)
  vtk_test_cxx_executable("${executable}" "${tests_variable}"
    RENDERING_FACTORY
    "${VTKPHONG_TESTING_CORE_DIR}/vtkPhongSharedDisplay.cxx")
  target_include_directories("${executable}" PRIVATE "${VTKPHONG_TESTING_CORE_DIR}")
  # The tests share one X connection per process (vtkPhongSharedDisplay.h).
  find_package(X11 REQUIRED)
  target_link_libraries("${executable}" PRIVATE X11::X11)
endfunction ()

# vtkphong_add_python_tests(BASELINES <dir> [SUFFIX <suffix> ARGS <arg>...] TESTS <name>...)
#
# One ctest per <name>.py of the calling Testing/Python directory, named
# vtkPhongPython-<name><suffix>, run as `python3 <name>.py <arg>... -B <baselines> -T
# <Testing/Temporary>`. A test fails on a non-zero exit, an "ERROR: " line, VTK's ERR| output
# or a traceback.
function (vtkphong_add_python_tests)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "BASELINES;SUFFIX" "TESTS;ARGS")
  foreach (test IN LISTS arg_TESTS)
    add_test(NAME "vtkPhongPython-${test}${arg_SUFFIX}"
      COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/${test}.py" ${arg_ARGS}
        -B "${arg_BASELINES}"
        -T "${VTKPHONG_TEST_OUTPUT_DIR}")
    set_tests_properties("vtkPhongPython-${test}${arg_SUFFIX}" PROPERTIES
      ENVIRONMENT "PYTHONPATH=${VTKPHONG_BUILD_PYTHONPATH}:${VTKPHONG_TESTING_CORE_DIR};VTKPHONG_VTK_CHANGES=${VTKPHONG_VTK_CHANGES}"
      FAIL_REGULAR_EXPRESSION "(\n|^)ERROR: ;ERR\\|;Traceback")
  endforeach ()
endfunction ()
