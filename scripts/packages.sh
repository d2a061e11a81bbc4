# Sourced by the set-up scripts: aniso_install_packages PACKAGE... installs the Debian 12
# packages that are missing (apt-get as root; otherwise prints the line to run and fails).
# ANISO_PACKAGES: what the build, its tests and their data need (setup.sh, sanitize.sh;
# glslang-tools: the Khronos reference compiler test_shader_portability checks the shaders with);
# the last two lines build and check the Debian package (CPack's dpkg-shlibdeps and file, the
# icons' PNGs, the man page, the validators and the MIME check of tests/packaging).
# ANISO_PARAVIEW_PACKAGES: what the ParaView plugin's stage adds (scripts/paraview.sh: ParaView
# 5.11, Qt5 SVG which its CMake files ask for, mpirun, and numpy and VTK's Python for the tests'
# comparisons).
ANISO_PACKAGES=(cmake g++ make pkg-config libvtk9-dev libvtk9-qt-dev qtbase5-dev libopenimageio-dev
  openimageio-tools libglm-dev libgtest-dev libbenchmark-dev xvfb xauth libgl1-mesa-dri
  blender-data nlohmann-json3-dev libtinygltf-dev libocct-data-exchange-dev
  libocct-modeling-algorithms-dev libocct-ocaf-dev libocct-foundation-dev libocct-modeling-data-dev
  assimp-testmodels glslang-tools
  dpkg-dev file librsvg2-bin help2man desktop-file-utils appstream lintian shared-mime-info
  libglib2.0-bin)
ANISO_PARAVIEW_PACKAGES=(paraview-dev libqt5svg5-dev openmpi-bin python3-numpy python3-vtk9)

aniso_install_packages() {
  local missing=() p
  for p in "$@"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q " ok installed$"; then
      missing+=("$p")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  if [ "$(id -u)" -eq 0 ]; then
    echo "aniso: installing missing packages: ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  else
    echo "aniso: missing Debian packages: ${missing[*]}" >&2
    echo "aniso: install them with: sudo apt-get install ${missing[*]}" >&2
    return 1
  fi
}

# aniso_unpack_package PACKAGE DIR: PACKAGE's files (its candidate version) unpacked under
# DIR/root without installing it, once per version (DIR/version). For python3-paraview, which
# Debian 12 cannot install beside python3-vtk9 (both ship the Python package vtkmodules), and
# whose files the ParaView plugin's build and tests need (paraview/CMakeLists.txt).
aniso_unpack_package() {
  local package="$1" dir="$2" version
  version="$(apt-cache policy "$package" | awk '/Candidate:/ {print $2}')"
  if [ -z "$version" ] || [ "$version" = "(none)" ]; then
    if [ "$(id -u)" -eq 0 ]; then
      apt-get update -qq
      version="$(apt-cache policy "$package" | awk '/Candidate:/ {print $2}')"
    fi
    if [ -z "$version" ] || [ "$version" = "(none)" ]; then
      echo "aniso: no Debian package $package to unpack (apt-get update?)" >&2
      return 1
    fi
  fi
  if [ -f "$dir/version" ] && [ "$(cat "$dir/version")" = "$version" ] && [ -d "$dir/root" ]; then
    return 0
  fi
  echo "aniso: unpacking $package $version into $dir"
  rm -rf "$dir"
  mkdir -p "$dir/deb"
  # apt-get download writes into the current directory; as root it warns that its sandbox
  # user cannot write there, which is harmless.
  (cd "$dir/deb" && apt-get download -qq "$package=$version" 2>/dev/null) ||
    { [ "$(id -u)" -eq 0 ] && apt-get update -qq &&
      (cd "$dir/deb" && apt-get download -qq "$package=$version" 2>/dev/null); } || {
      echo "aniso: could not download $package $version" >&2
      return 1
    }
  dpkg-deb -x "$dir"/deb/*.deb "$dir/root"
  rm -rf "$dir/deb"
  echo "$version" >"$dir/version"
}
