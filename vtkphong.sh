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
#                          (docs/tradeoff.md, .csv and .png)
#
# The build directory is ./build (override with VTKPHONG_BUILD_DIR).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${VTKPHONG_BUILD_DIR:-$root/build}"
jobs="$(nproc 2>/dev/null || echo 2)"

packages=(
  cmake g++ make pkg-config
  libvtk9-dev python3-vtk9 python3-numpy python3-matplotlib
  libopenmesh-dev libglm-dev libopenimageio-dev openimageio-tools
  xvfb xauth libgl1-mesa-dri
  libcgal-demo
)

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
  for package in "${packages[@]}"; do
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
    install_packages
    build_project
    cd "$build"
    with_display ctest --output-on-failure -j "$jobs"
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
      "$root/Testing/Benchmarks/vtkPhongTradeStudy.py" --out "$root/docs"
    ;;
  extremes)
    install_packages
    build_project
    mkdir -p "$build/Testing/Temporary"
    with_display "$build/bin/vtkRenderingPhongCxxTests" TestPhongExtremes \
      -T "$build/Testing/Temporary"
    ;;
  *)
    sed -n '2,15p' "$0" >&2
    exit 2
    ;;
esac
