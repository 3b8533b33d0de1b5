#!/usr/bin/env bash
# Installs every Debian package MeshEdit needs to build and test (OpenSubdiv is the tests'
# subdivision oracle; libcgal-demo holds the scanned bunny of the simplify and remesh golden
# images; pybind11, numpy and pytest build and test the Python module; libmeshoptimizer decodes
# EXT_meshopt_compression glTF files and is also the simplification bench's anchor; Eigen
# solves smoothing's and fairing's sparse systems); with --bench also the other benchmark
# anchors (OpenMesh, CGAL, Assimp, Open3D for the Python rows) and perf, which only `make bench`
# needs; with --fuzz clang and its libFuzzer runtime (`make fuzz`); with --clang clang alone
# (`make test-clang`). Idempotent: when everything is present it only runs dpkg queries (well
# under a second). Without apt-get it prints the package names for dnf, pacman or Homebrew and
# stops (docs/building.md).
set -euo pipefail

bench=0
fuzz=0
clang=0
for arg in "$@"; do
    case "$arg" in
        --bench) bench=1 ;;
        --fuzz) fuzz=1 ;;
        --clang) clang=1 ;;
        *) echo "usage: $0 [--bench] [--fuzz] [--clang]" >&2; exit 2 ;;
    esac
done

packages=(
    build-essential cmake ninja-build pkg-config
    libgtest-dev libgmock-dev libbenchmark-dev
    clang-format
    libpugixml-dev libtinygltf-dev nlohmann-json3-dev libcli11-dev libmeshoptimizer-dev
    assimp-utils assimp-testmodels
    libosmesa6-dev libegl-dev libegl-mesa0 libgl-dev libglm-dev libopenimageio-dev openimageio-tools
    libglfw3-dev libimgui-dev libstb-dev libopengl-dev libgl1-mesa-dri
    libosd-dev libcgal-demo libeigen3-dev
    fonts-dejavu-core xvfb xdotool imagemagick x11-utils
    pybind11-dev python3-dev python3-numpy python3-pytest
)
if [ "$fuzz" -eq 1 ]; then
    packages+=(clang libclang-rt-14-dev)
fi
if [ "$clang" -eq 1 ]; then
    packages+=(clang)
fi
if [ "$bench" -eq 1 ]; then
    packages+=(libopenmesh-dev libcgal-dev libassimp-dev linux-perf python3-open3d)
fi

# Not Debian or Ubuntu: name the packages for the manager found (a best effort, untested here;
# docs/building.md lists every dependency) and stop. CMake names whatever is still missing.
if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
    if command -v dnf >/dev/null 2>&1; then
        echo "install-deps: this is not Debian; on Fedora install:" >&2
        echo "  sudo dnf install gcc-c++ cmake ninja-build pkgconf-pkg-config gtest-devel gmock-devel google-benchmark-devel clang-tools-extra pugixml-devel eigen3-devel tinygltf-devel json-devel cli11-devel mesa-libOSMesa-devel libglvnd-devel mesa-libEGL-devel glm-devel OpenImageIO-devel glfw-devel imgui-devel stb-devel opensubdiv-devel dejavu-sans-fonts xorg-x11-server-Xvfb xdotool ImageMagick xorg-x11-utils pybind11-devel python3-devel python3-numpy python3-pytest" >&2
    elif command -v pacman >/dev/null 2>&1; then
        echo "install-deps: this is not Debian; on Arch install:" >&2
        echo "  sudo pacman -S --needed base-devel cmake ninja pkgconf gtest benchmark clang pugixml eigen tinygltf nlohmann-json cli11 mesa libglvnd glm openimageio glfw imgui opensubdiv ttf-dejavu xorg-server-xvfb xdotool imagemagick xorg-xdpyinfo pybind11 python-numpy python-pytest" >&2
    elif command -v brew >/dev/null 2>&1; then
        echo "install-deps: this is not Debian; with Homebrew install:" >&2
        echo "  brew install cmake ninja pkg-config googletest google-benchmark clang-format pugixml eigen nlohmann-json cli11 mesa glm openimageio glfw opensubdiv pybind11 numpy" >&2
        echo "  (tinygltf, Dear ImGui and stb: from their sources; EGL/OSMesa headless rendering needs Mesa)" >&2
    else
        echo "install-deps: no apt-get, dnf, pacman or brew found; docs/building.md lists what MeshEdit needs" >&2
    fi
    exit 1
fi

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
        SUDO="sudo"
    else
        echo "install-deps: missing packages (${missing[*]}) and not root; install them with apt-get" >&2
        exit 1
    fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
