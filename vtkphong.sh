#!/usr/bin/env bash
# vtkPhong's one entry point on Debian 12 (bookworm) and Debian 13 (trixie): installs what
# is missing (apt), configures and builds, then does the job asked for.
#
#   ./vtkphong.sh render   render the default scene (CGAL's bunny, three lights,
#                          Blinn-Phong) and print the image's path
#   ./vtkphong.sh test     run every test (ctest under Xvfb)
#   ./vtkphong.sh bench    run the benchmarks and print their tables
#   ./vtkphong.sh bench-growth [sizes]
#                          big meshes against stock VTK, one process per measurement: a
#                          closed sphere and an open terrain, 1M to 32M triangles (or the
#                          comma-separated sizes given), with and without input normals
#                          (docs/results/performance.md)
#   ./vtkphong.sh budget-sweep [count] [seed]
#                          the error budget on 1000 random scenes (or count), a 360-frame
#                          orbit and the 51-scene matrix, every frame within its budget
#                          (ctest runs 40, 120 and the matrix; docs/lighting-model.md)
#   ./vtkphong.sh extremes run the numerical-stability suite (float GPU against
#                          the double-precision reference) and print its table
#   ./vtkphong.sh study    regenerate the speed/accuracy trade study
#                          (docs/results/tradeoff.md, .csv and .png)
#   ./vtkphong.sh paraview build the ParaView plugin against paraview-dev's VTK (5.11 on
#                          Debian 12, 5.13 on Debian 13; into ./build-paraview) and run its
#                          pvbatch / MPI / pvserver tests; `test` runs this stage too
#   ./vtkphong.sh test-debian13 [command]
#                          run `test` (or another command of this script) on Debian 13
#                          (VTK 9.3, ParaView 5.13) from a Debian 12 host: a trixie root made
#                          by debootstrap (VTKPHONG_DEBIAN13_ROOT, default
#                          /var/tmp/vtkphong/trixie), this tree bind-mounted into it, builds
#                          in ./build-debian13 and ./build-paraview-debian13
#   ./vtkphong.sh test-forky [command]
#                          the same on Debian testing "forky" (VTK 9.6, ParaView 6.1 on the
#                          system VTK): VTKPHONG_FORKY_ROOT, default /var/tmp/vtkphong/forky;
#                          builds in ./build-forky and ./build-paraview-forky
#   ./vtkphong.sh build    install what is missing and build (no test)
#   ./vtkphong.sh test-asan
#                          build with AddressSanitizer + UndefinedBehaviorSanitizer
#                          (into ./build-asan) and run the C++ tests; any report in
#                          the project's own code fails (docs/sanitizers.md)
#   ./vtkphong.sh fuzz     vtkphong-render on all of assimp's test corpus, then mutation
#                          fuzzing of its readers (1000 mutants per format); prints the
#                          tables of docs/io.md
#   ./vtkphong.sh paraview-bench
#                          time Phong Surface against Surface in pvbatch on 1 and 2
#                          MPI ranks (a 4M-triangle sphere; docs/paraview.md), then what
#                          an update costs with the normals across pieces (1M triangles)
#   ./vtkphong.sh paraview-bench-growth
#                          first frame, steady frame and peak memory of Phong Surface
#                          against Surface in pvbatch, 16M triangles, 1 and 2 ranks, one
#                          process per measurement (docs/results/performance.md)
#
# The build directory is ./build (override with VTKPHONG_BUILD_DIR); the ParaView
# build's is ./build-paraview (VTKPHONG_PARAVIEW_BUILD_DIR).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${VTKPHONG_BUILD_DIR:-$root/build}"
paraview_build="${VTKPHONG_PARAVIEW_BUILD_DIR:-$root/build-paraview}"
jobs="$(nproc 2>/dev/null || echo 2)"

# What each Debian release needs, in one place, chosen from /etc/os-release: the packages
# and ParaView's version, which names its CMake package and plugin directories. Debian 12
# (bookworm): VTK 9.1, ParaView 5.11. Debian 13 (trixie): VTK 9.3, ParaView 5.13, OpenMesh 11,
# OpenImageIO 2.5. Debian testing (forky): VTK 9.6, ParaView 6.1 on the system VTK,
# OpenImageIO 3.1, assimp 6. The package names are the same (the t64 renames touch only
# libraries these pull in), so the lists are shared and a release adds its own to them here.
packages=(
  cmake g++ make pkg-config
  libvtk9-dev python3-vtk9 python3-numpy python3-matplotlib
  libopenmesh-dev libglm-dev libopenimageio-dev openimageio-tools
  xvfb xauth libgl1-mesa-dri
  libcgal-demo universal-ctags
  libassimp-dev assimp-testmodels assimp-utils
)
paraview_packages=(paraview paraview-dev openmpi-bin)
# Clients whose own scenes the tests draw through the switch (Testing/Clients).
client_packages=(python3-vedo)
release="$(. /etc/os-release && echo "${VERSION_CODENAME:-}")"
# ParaView on its own VTK (Debian 12 and 13): python3-paraview conflicts with python3-vtk9,
# so its .deb is unpacked into the ParaView build tree. From Debian testing on, ParaView is
# built on the system VTK and python3-paraview installs beside python3-vtk9.
paraview_python_installed=0
case "$release" in
  trixie)
    paraview_version=5.13
    client_packages+=(python3-pyvista) # Debian 12 has no PyVista
    ;;
  forky)
    paraview_version=6.1
    client_packages+=(python3-pyvista)
    paraview_packages+=(python3-paraview)
    paraview_python_installed=1
    ;;
  *) paraview_version=5.11 ;; # bookworm
esac

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
  if [ "$paraview_python_installed" = 1 ]; then
    unpacked=/
  elif [ ! -d "$unpacked/usr/lib/python3/dist-packages/paraview" ]; then
    mkdir -p "$paraview_build/deb"
    (cd "$paraview_build/deb" && apt-get download python3-paraview)
    dpkg-deb -x "$paraview_build"/deb/python3-paraview_*.deb "$unpacked"
  fi
  cmake -S "$root" -B "$paraview_build" -DCMAKE_BUILD_TYPE=Release -Wno-dev \
    -DVTKPHONG_PARAVIEW=ON -DVTKPHONG_PARAVIEW_PYTHON_ROOT="$unpacked" \
    -DVTKPHONG_PARAVIEW_VERSION="$paraview_version"
  cmake --build "$paraview_build" -j "$jobs"
}

run_paraview_tests() {
  cd "$paraview_build"
  with_display ctest --output-on-failure
}

# The C++ tests under AddressSanitizer and UndefinedBehaviorSanitizer. Python tests are
# left out: an instrumented module in an uninstrumented interpreter needs the runtime
# preloaded, and the C++ tests reach the same module code.
build_sanitized() {
  local flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
  cmake -S "$root" -B "$root/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -Wno-dev \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined"
  cmake --build "$root/build-asan" -j "$jobs"
}

run_sanitized_tests() {
  # Leaks: VTK's and Mesa's singletons live until exit and are reported as leaks there;
  # the suppressions (Testing/Core/sanitizers.supp) name them, nothing of the project's.
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:symbolize=1"
  export LSAN_OPTIONS="suppressions=$root/Testing/Core/sanitizers.supp:print_suppressions=0"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  # LeakSanitizer's tracer stops every thread at exit; with llvmpipe's rasterizer threads it
  # crashed once in 49 tests under load (the test passed alone): rasterize on one thread.
  export LP_NUM_THREADS=0
  cd "$root/build-asan"
  with_display ctest --output-on-failure -R "Cxx-" -j "$jobs"
}

with_display() {
  # -noreset: an X server resets when its last client leaves and refuses connections while it
  # does; with tests starting and ending in parallel one of them met that (CI, 2026-11-27).
  xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$@"
}

# Debian 13 (trixie) and Debian testing (forky) from a Debian 12 host: a root made by
# debootstrap (made once and reused), this tree bind-mounted into it at the same path, and
# `./vtkphong.sh test` (or another command) run inside, which installs that release's
# packages with apt in the root. Mounts are undone whatever happens.
release_mounts=()

release_root() { # release_root CODENAME
  case "$1" in
    trixie) echo "${VTKPHONG_DEBIAN13_ROOT:-/var/tmp/vtkphong/trixie}" ;;
    forky) echo "${VTKPHONG_FORKY_ROOT:-/var/tmp/vtkphong/forky}" ;;
  esac
}

release_build_suffix() { # the build directories' suffix: build-debian13, build-forky
  case "$1" in
    trixie) echo debian13 ;;
    *) echo "$1" ;;
  esac
}

release_unmount() {
  local i
  for ((i = ${#release_mounts[@]} - 1; i >= 0; i--)); do
    umount "${release_mounts[i]}" 2>/dev/null || umount -l "${release_mounts[i]}" || true
  done
  release_mounts=()
}

release_clear_stale_mounts() { # release_clear_stale_mounts ROOT
  # A run killed outright (SIGKILL: no EXIT trap) leaves its mounts in the root, and mounting
  # over them fails ("sysfs already mounted": CI, 2026-11-28). This runs under the root's lock
  # (no other stage is using them) and, where unshare works, in the stage's own mount
  # namespace (the host's are left alone).
  local target
  awk -v prefix="$1/" 'index($5, prefix) == 1 { print $5 }' /proc/self/mountinfo | sort -r |
    while read -r target; do
      umount "$target" 2>/dev/null || umount -l "$target" || true
    done
}

release_mount() { # release_mount ROOT SOURCE TARGET-IN-ROOT [mount options...]
  local target="$1$3" source="$2"
  shift 3
  mkdir -p "$target"
  mount "$@" "$source" "$target"
  release_mounts+=("$target")
}

release_create_root() { # release_create_root CODENAME ROOT
  local codename="$1" root_dir="$2"
  [ -f "$root_dir/.vtkphong-root" ] && return 0
  command -v debootstrap >/dev/null 2>&1 ||
    { apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y debootstrap; }
  # Into a scratch directory first: an interrupted debootstrap is never mistaken for a root.
  local partial="$root_dir.partial" script=()
  # Bookworm's debootstrap has no script for testing: sid's bootstraps it.
  [ -e "/usr/share/debootstrap/scripts/$codename" ] || script=(/usr/share/debootstrap/scripts/sid)
  rm -rf "$partial"
  mkdir -p "$(dirname "$root_dir")"
  debootstrap --variant=minbase "$codename" "$partial" http://deb.debian.org/debian "${script[@]}"
  # Testing's Release file can be past its Valid-Until on the mirror.
  echo 'Acquire::Check-Valid-Until "false";' >"$partial/etc/apt/apt.conf.d/99vtkphong-valid"
  # Services never start in the root (package scripts ask policy-rc.d).
  printf '#!/bin/sh\nexit 101\n' >"$partial/usr/sbin/policy-rc.d"
  chmod +x "$partial/usr/sbin/policy-rc.d"
  touch "$partial/.vtkphong-root"
  mv "$partial" "$root_dir"
}

test_release() { # test_release CODENAME [COMMAND]
  local codename="$1" inner="${2:-test}"
  if [ "$(id -u)" -ne 0 ]; then
    # chroot and mount need root; the environment (root dir, compiler launcher) goes along.
    command -v sudo >/dev/null 2>&1 || { echo "vtkphong.sh: run as root" >&2; exit 1; }
    exec sudo --preserve-env "$root/vtkphong.sh" "test-$(release_build_suffix "$codename")" \
      "$inner"
  fi
  local root_dir suffix
  root_dir="$(release_root "$codename")"
  suffix="$(release_build_suffix "$codename")"
  if [ -z "${VTKPHONG_OWN_MOUNT_NAMESPACE:-}" ] &&
    unshare --mount --propagation private true 2>/dev/null; then
    # In a mount namespace of its own, the stage's mounts vanish with it however it ends, and
    # two stages sharing a root (CI beside a developer's run) never see each other's.
    VTKPHONG_OWN_MOUNT_NAMESPACE=1 exec unshare --mount --propagation private \
      "$root/vtkphong.sh" "test-$suffix" "$inner"
  fi
  # One stage at a time per root (waiting, not failing): two at once, CI beside a
  # developer's run, would race to make it and contend for its package database. The lock
  # goes with this process, however it ends; what runs in the root does not inherit it (a
  # server left running there would hold it for ever).
  mkdir -p "$(dirname "$root_dir")"
  local lock
  exec {lock}>"$root_dir.lock"
  flock "$lock"
  release_create_root "$codename" "$root_dir"
  release_clear_stale_mounts "$root_dir"
  cp /etc/resolv.conf "$root_dir/etc/resolv.conf"
  # Unmount on every way out: a signal exits, and exiting runs the EXIT trap.
  trap release_unmount EXIT
  trap 'exit 130' INT TERM HUP
  release_mount "$root_dir" proc /proc -t proc
  release_mount "$root_dir" sysfs /sys -t sysfs
  release_mount "$root_dir" /dev /dev --bind
  release_mount "$root_dir" /dev/pts /dev/pts --bind
  release_mount "$root_dir" /dev/shm /dev/shm --bind
  release_mount "$root_dir" "$root" "$root" --bind
  local launcher=()
  if [ -n "${CMAKE_CXX_COMPILER_LAUNCHER:-}" ] && [ -d "${CCACHE_DIR:-$HOME/.ccache}" ]; then
    # Share the host's compiler cache (its base_dir makes hits path-independent).
    release_mount "$root_dir" "${CCACHE_DIR:-$HOME/.ccache}" /root/.ccache --bind
    chroot "$root_dir" sh -c 'command -v ccache >/dev/null' ||
      chroot "$root_dir" env DEBIAN_FRONTEND=noninteractive \
        sh -c 'apt-get update && apt-get install -y --no-install-recommends ccache' {lock}>&-
    launcher=(CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache)
  fi
  local status=0
  chroot "$root_dir" /usr/bin/env -i HOME=/root LANG=C.UTF-8 \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin "${launcher[@]}" \
    VTKPHONG_BUILD_DIR="$root/build-$suffix" \
    VTKPHONG_PARAVIEW_BUILD_DIR="$root/build-paraview-$suffix" \
    "$root/vtkphong.sh" "$inner" {lock}>&- || status=$?
  release_unmount
  trap - EXIT INT TERM HUP
  return "$status"
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
    install_packages "${paraview_packages[@]}" "${client_packages[@]}"
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
  test-debian13)
    test_release trixie "${2:-test}"
    ;;
  test-forky)
    test_release forky "${2:-test}"
    ;;
  build)
    install_packages
    build_project
    ;;
  paraview-bench)
    install_packages "${paraview_packages[@]}"
    build_paraview_plugin
    plugin="$paraview_build/lib/paraview-$paraview_version/plugins/PhongLighting/PhongLighting.so"
    export PYTHONPATH="$paraview_build/python3-paraview/usr/lib/python3/dist-packages"
    for ranks in 1 2; do
      with_display timeout 900 mpiexec --allow-run-as-root --oversubscribe -np "$ranks" \
        pvbatch --disable-xdisplay-test "$root/ParaView/Testing/BenchPhongParaView.py" \
        --plugin "$plugin"
    done
    for ranks in 1 2; do
      with_display timeout 900 mpiexec --allow-run-as-root --oversubscribe -np "$ranks" \
        pvbatch --disable-xdisplay-test "$root/ParaView/Testing/BenchPhongParaViewNormals.py" \
        --plugin "$plugin"
    done
    ;;
  paraview-bench-growth)
    install_packages "${paraview_packages[@]}"
    build_paraview_plugin
    export PYTHONPATH="$paraview_build/python3-paraview/usr/lib/python3/dist-packages"
    for normals in "" --normals; do
      with_display /usr/bin/python3 "$root/ParaView/Testing/BenchPhongParaViewGrowth.py" $normals \
        --plugin "$paraview_build/lib/paraview-$paraview_version/plugins/PhongLighting/PhongLighting.so"
    done
    ;;
  bench)
    install_packages
    build_project
    extract_meshes data/meshes/bunny00.off data/meshes/refined_elephant.off
    with_display "$build/bin/vtkPhongBenchmark" "$build/data/meshes/bunny00.off" \
      "$build/data/meshes/refined_elephant.off"
    "$build/bin/vtkOpenMeshNormalsBenchmark" "$build/data/meshes/refined_elephant.off"
    PYTHONPATH="$build/lib/python3/dist-packages" with_display /usr/bin/python3 \
      "$root/Testing/Benchmarks/vtkPhongProgramMemory.py"
    PYTHONPATH="$build/lib/python3/dist-packages" with_display /usr/bin/python3 \
      "$root/Testing/Benchmarks/vtkPhongDirectionalCost.py"
    PYTHONPATH="$build/lib/python3/dist-packages" with_display /usr/bin/python3 \
      "$root/Testing/Benchmarks/vtkPhongManyActors.py" 1 4 5 50 200
    ;;
  bench-growth)
    install_packages
    build_project
    with_display python3 "$root/Testing/Benchmarks/vtkPhongGrowth.py" \
      --program "$build/bin/vtkPhongBigMeshFrame" --sizes "${2:-1e6,2e6,8e6,16e6,32e6}"
    ;;
  study)
    install_packages
    build_project
    PYTHONPATH="$build/lib/python3/dist-packages" with_display /usr/bin/python3 \
      "$root/Testing/Benchmarks/vtkPhongTradeStudy.py" --out "$root/docs/results"
    ;;
  test-asan)
    install_packages
    build_sanitized
    run_sanitized_tests
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
  budget-sweep)
    install_packages
    build_project
    extract_meshes data/meshes/bunny00.off
    mkdir -p "$build/Testing/Temporary"
    with_display "$build/bin/vtkRenderingPhongCxxTests" TestPhongErrorBudget \
      "$build/data/meshes/bunny00.off" --random "${2:-1000}" --seed "${3:-2026}" --orbit 360 \
      -T "$build/Testing/Temporary"
    ;;
  extremes)
    install_packages
    build_project
    mkdir -p "$build/Testing/Temporary"
    with_display "$build/bin/vtkRenderingPhongCxxTests" TestPhongExtremes \
      -T "$build/Testing/Temporary"
    ;;
  *)
    sed -n '2,/^set -euo/p' "$0" | sed '$d' >&2
    exit 2
    ;;
esac
