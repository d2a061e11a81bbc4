# Sourced by the set-up scripts: aniso_install_packages PACKAGE... installs the Debian 12
# packages that are missing (apt-get as root; otherwise prints the line to run and fails).
# ANISO_PACKAGES: what the build, its tests and their data need (setup.sh, sanitize.sh); the last
# two lines build and check the Debian package (CPack's dpkg-shlibdeps and file, the icons' PNGs,
# the man page, the validators and the MIME check of tests/packaging).
ANISO_PACKAGES=(cmake g++ make pkg-config libvtk9-dev libvtk9-qt-dev qtbase5-dev libopenimageio-dev
  openimageio-tools libglm-dev libgtest-dev libbenchmark-dev xvfb xauth libgl1-mesa-dri
  blender-data nlohmann-json3-dev libtinygltf-dev libocct-data-exchange-dev
  libocct-modeling-algorithms-dev libocct-ocaf-dev libocct-foundation-dev libocct-modeling-data-dev
  assimp-testmodels
  dpkg-dev file librsvg2-bin help2man desktop-file-utils appstream lintian shared-mime-info
  libglib2.0-bin)

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
