# The install tree is usable on its own: `cmake --install` into a fresh
# prefix, then build Examples/Cxx against it with find_package(vtkPhong) as
# any other project would, run that program, import vtkphong from the
# prefix with VTK's Python, and render with the prefix's vtkphong-render.
#
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DMESH=... -DPYTHON=... -P TestInstallConsumer.cmake

foreach (variable IN ITEMS BUILD_DIR SOURCE_DIR MESH PYTHON PYTHON_DESTINATION)
  if (NOT DEFINED ${variable})
    message(FATAL_ERROR "TestInstallConsumer.cmake needs -D${variable}=...")
  endif ()
endforeach ()

set(work "${BUILD_DIR}/Testing/Temporary/InstallConsumer")
set(prefix "${work}/prefix")
set(consumer "${work}/consumer")
file(REMOVE_RECURSE "${work}")

function (run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "FAILED (${result}): ${ARGN}\n${output}")
  endif ()
  message(STATUS "ok: ${ARGN}")
  set(last_output "${output}" PARENT_SCOPE)
endfunction ()

run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
foreach (file IN ITEMS
    "lib/cmake/vtkPhong/vtkPhongConfig.cmake"
    "lib/cmake/vtkPhong/vtkPhong-targets.cmake"
    "include/vtkPhong/vtkPhongPolyDataMapper.h"
    "${PYTHON_DESTINATION}/vtkphong/__init__.py"
    "${PYTHON_DESTINATION}/vtkphong/render.py"
    "bin/vtkphong-render")
  if (NOT EXISTS "${prefix}/${file}")
    message(FATAL_ERROR "the install tree lacks ${file}")
  endif ()
endforeach ()

run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}/Examples/Cxx" -B "${consumer}" -Wno-dev
  -DCMAKE_BUILD_TYPE=Release "-DvtkPhong_DIR=${prefix}/lib/cmake/vtkPhong")
run("${CMAKE_COMMAND}" --build "${consumer}")
run("${consumer}/PhongDefaultScene" "${MESH}" "${work}/consumer.png" 320 240)
if (NOT EXISTS "${work}/consumer.png")
  message(FATAL_ERROR "the consumer wrote no image")
endif ()

# A plain VTK program (no vtkPhong name in it) linked with the overrides module's autoinit.
run("${consumer}/StockVTKProgram" "${work}/stock-program.png")
if (NOT last_output MATCHES "mapper: vtkPhongPolyDataMapper")
  message(FATAL_ERROR "the plain VTK program did not get vtkPhong's mapper: ${last_output}")
endif ()

run("${CMAKE_COMMAND}" -E env "PYTHONPATH=${prefix}/${PYTHON_DESTINATION}" "${PYTHON}" -c
  "import vtkphong, sys; m = vtkphong.vtkPhongPolyDataMapper(); p = vtkphong.vtkPhongProperty(); \
p.SetShininess(5000.0); assert p.GetShininess() == 5000.0; \
assert vtkphong.__file__.startswith(sys.argv[1]), vtkphong.__file__; print('python ok')" "${prefix}")

# The installed command finds the installed package (no PYTHONPATH).
run("${prefix}/bin/vtkphong-render" "${MESH}" -o "${work}/cli.png" --size 160x120 --quiet)
if (NOT EXISTS "${work}/cli.png")
  message(FATAL_ERROR "the installed vtkphong-render wrote no image")
endif ()
message(STATUS "the install tree at ${prefix} works")
