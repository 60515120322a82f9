#!/usr/bin/env bash
# vtkPhong's one entry point on Debian 12: installs what is missing (apt),
# configures and builds, then does the job asked for.
#
#   ./vtkphong.sh render   render the default scene (CGAL's bunny, three lights,
#                          Blinn-Phong) and print the image's path
#   ./vtkphong.sh test     run every test (ctest under Xvfb)
#   ./vtkphong.sh bench    run the benchmarks and print their tables
#   ./vtkphong.sh extremes run the numerical-stability suite (float GPU against
#                          the double-precision reference) and print its table
#   ./vtkphong.sh study    regenerate the speed/accuracy trade study
#                          (docs/results/tradeoff.md, .csv and .png)
#   ./vtkphong.sh paraview build the ParaView 5.11 plugin against paraview-dev's VTK
#                          (into ./build-paraview) and run its pvbatch / MPI / pvserver
#                          tests; `test` runs this stage too after the VTK tests
#   ./vtkphong.sh fuzz     vtkphong-render on all of assimp's test corpus, then mutation
#                          fuzzing of its readers (1000 mutants per format); prints the
#                          tables of docs/io.md
#   ./vtkphong.sh paraview-bench
#                          time Phong Surface against Surface in pvbatch on 1 and 2
#                          MPI ranks (a 4M-triangle sphere; docs/paraview.md)
#
# The build directory is ./build (override with VTKPHONG_BUILD_DIR); the ParaView
# build's is ./build-paraview (VTKPHONG_PARAVIEW_BUILD_DIR).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${VTKPHONG_BUILD_DIR:-$root/build}"
paraview_build="${VTKPHONG_PARAVIEW_BUILD_DIR:-$root/build-paraview}"
jobs="$(nproc 2>/dev/null || echo 2)"

packages=(
  cmake g++ make pkg-config
  libvtk9-dev python3-vtk9 python3-numpy python3-matplotlib
  libopenmesh-dev libglm-dev libopenimageio-dev openimageio-tools
  xvfb xauth libgl1-mesa-dri
  libcgal-demo universal-ctags
  libassimp-dev assimp-testmodels assimp-utils
)
# The ParaView stage. python3-paraview conflicts with python3-vtk9 and is never
# installed: its .deb is unpacked into the ParaView build tree instead.
paraview_packages=(paraview paraview-dev openmpi-bin)

as_root() {
  if [ "$(id -u)" -eq 0 ]; then
    "$@"
  elif command -v sudo >/dev/null 2>&1; then
    sudo "$@"
  else
    echo "vtkphong.sh: need root (or sudo) to install: ${missing[*]}" >&2
    exit 1
  fi
}

install_packages() {
  missing=()
  for package in "${packages[@]}" "$@"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
      missing+=("$package")
  done
  if [ "${#missing[@]}" -gt 0 ]; then
    echo "-- installing: ${missing[*]}"
    as_root apt-get update
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
  fi
}

build_project() {
  # VTK's Python is /usr/bin/python3; CMake is told so in CMakeLists.txt.
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -Wno-dev
  cmake --build "$build" -j "$jobs"
}

# CGAL's meshes ship in libcgal-demo's tarball; they are extracted, never committed.
extract_meshes() {
  mkdir -p "$build/data"
  tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$build/data" --strip-components=1 "$@"
}

build_paraview_plugin() {
  local unpacked="$paraview_build/python3-paraview"
  if [ ! -d "$unpacked/usr/lib/python3/dist-packages/paraview" ]; then
    mkdir -p "$paraview_build/deb"
    (cd "$paraview_build/deb" && apt-get download python3-paraview)
    dpkg-deb -x "$paraview_build"/deb/python3-paraview_*.deb "$unpacked"
  fi
  cmake -S "$root" -B "$paraview_build" -DCMAKE_BUILD_TYPE=Release -Wno-dev \
    -DVTKPHONG_PARAVIEW=ON -DVTKPHONG_PARAVIEW_PYTHON_ROOT="$unpacked"
  cmake --build "$paraview_build" -j "$jobs"
}

run_paraview_tests() {
  cd "$paraview_build"
  with_display ctest --output-on-failure
}

with_display() {
  xvfb-run -a -s "-screen 0 1280x1024x24" "$@"
}

command="${1:-}"
case "$command" in
  render)
    install_packages
    build_project
    extract_meshes data/meshes/bunny00.off
    with_display "$build/bin/PhongDefaultScene" "$build/data/meshes/bunny00.off" \
      "$build/default-scene.png"
    ;;
  test)
    install_packages "${paraview_packages[@]}"
    build_project
    (cd "$build" && with_display ctest --output-on-failure -j "$jobs")
    build_paraview_plugin
    run_paraview_tests
    ;;
  paraview)
    install_packages "${paraview_packages[@]}"
    build_paraview_plugin
    run_paraview_tests
    ;;
  paraview-bench)
    install_packages "${paraview_packages[@]}"
    build_paraview_plugin
    plugin="$paraview_build/lib/paraview-5.11/plugins/PhongLighting/PhongLighting.so"
    export PYTHONPATH="$paraview_build/python3-paraview/usr/lib/python3/dist-packages"
    for ranks in 1 2; do
      with_display timeout 900 mpiexec --allow-run-as-root --oversubscribe -np "$ranks" \
        pvbatch --disable-xdisplay-test "$root/ParaView/Testing/BenchPhongParaView.py" \
        --plugin "$plugin"
    done
    ;;
  bench)
    install_packages
    build_project
    extract_meshes data/meshes/bunny00.off data/meshes/refined_elephant.off
    with_display "$build/bin/vtkPhongBenchmark" "$build/data/meshes/bunny00.off" \
      "$build/data/meshes/refined_elephant.off"
    "$build/bin/vtkOpenMeshNormalsBenchmark" "$build/data/meshes/refined_elephant.off"
    ;;
  study)
    install_packages
    build_project
    PYTHONPATH="$build/lib/python3/dist-packages" with_display /usr/bin/python3 \
      "$root/Testing/Benchmarks/vtkPhongTradeStudy.py" --out "$root/docs/results"
    ;;
  fuzz)
    install_packages
    build_project
    export PYTHONPATH="$build/lib/python3/dist-packages"
    mkdir -p "$build/Testing/Temporary"
    with_display /usr/bin/python3 "$root/Testing/Python/TestPhongAssimpCorpus.py" \
      "$build/bin/vtkphong-render" -T "$build/Testing/Temporary" || true
    with_display /usr/bin/python3 "$root/Testing/Python/TestPhongFuzzReaders.py" \
      "$build/bin/vtkphong-render" -T "$build/Testing/Temporary" --count 1000 --cli-sample 50
    ;;
  extremes)
    install_packages
    build_project
    mkdir -p "$build/Testing/Temporary"
    with_display "$build/bin/vtkRenderingPhongCxxTests" TestPhongExtremes \
      -T "$build/Testing/Temporary"
    ;;
  *)
    sed -n '2,24p' "$0" >&2
    exit 2
    ;;
esac
